// Lifted formulas: terms, atoms, numeric expressions and conditions in
// negation normal form over the variable slots of an enclosing schema. Shared
// by action schemas, derived rules, the goal and PDDL 3 constraints.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/ids.h"

namespace alplan {

// A term of a lifted formula: a variable slot of the enclosing schema (its
// parameters first, then quantified variables) or an object.
struct LiftedTerm {
  bool is_variable = false;
  std::uint32_t index = 0;  // variable slot, or ObjectId
  bool operator==(const LiftedTerm&) const = default;
};

struct LiftedAtom {
  PredicateId predicate = kNoId;
  std::vector<LiftedTerm> args;
};

struct LiftedFunctionTerm {
  FunctionId function = kNoId;
  std::vector<LiftedTerm> args;
};

struct LiftedExpression {
  enum class Kind : unsigned char {
    Constant, Function, Add, Subtract, Multiply, Divide, Negate, Duration, TotalTime,
    IsViolated,  // (is-violated name) in a PDDL 3 metric
  };
  Kind kind = Kind::Constant;
  double value = 0.0;
  std::uint32_t preference = kNoId;  // IsViolated: index into TrajectoryConstraints::preferences
  LiftedFunctionTerm term;  // Function
  std::vector<LiftedExpression> operands;
};

// A quantified variable: its slot and the objects it ranges over.
struct QuantifiedVariable {
  std::uint32_t slot = 0;
  TypeId type = kNoId;
  std::string name;
};

// Negation normal form: negation only on atoms, equalities and comparisons
// (a negated comparison is stored with the opposite comparison).
struct LiftedCondition {
  enum class Kind : unsigned char { True, False, And, Or, Atom, Equality, Comparison, Forall, Exists };
  Kind kind = Kind::True;
  bool positive = true;  // Atom, Equality
  LiftedAtom atom;
  LiftedTerm left, right;  // Equality
  pddl::Comparison comparison = pddl::Comparison::Equal;
  std::vector<LiftedExpression> sides;  // Comparison: left, right
  std::vector<QuantifiedVariable> variables;
  std::vector<LiftedCondition> children;
};

}  // namespace alplan
