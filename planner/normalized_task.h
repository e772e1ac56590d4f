// The first pass of grounding: the PDDL AST made plain (Fast Downward's
// translator calls this normalisation). Names become ids, types become object
// sets, conditions are in negation normal form with `imply` removed, durative
// conditions and effects are split by time, and effects are flattened into
// primitive effects with their enclosing forall variables and when-condition.
// Nothing here is ground yet except the initial state, the timed initial
// literals and the goal (which may still quantify).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/ids.h"
#include "planner/lifted_formula.h"
#include "planner/trajectory_constraints.h"

namespace alplan {

enum class Moment : unsigned char { Start, End };

// One add, delete or numeric change, with what encloses it. A continuous
// effect (PDDL 2.1 level 4, `(increase f (* #t rate))` untimed in a durative
// action) keeps `assign` Increase or Decrease and its rate in `value`: the
// change per time unit while the action runs.
struct PrimitiveEffect {
  enum class Kind : unsigned char { Add, Delete, Numeric, Continuous };
  Kind kind = Kind::Add;
  Moment moment = Moment::Start;  // instantaneous actions use Start
  std::vector<QuantifiedVariable> forall;
  LiftedCondition condition;  // True when unconditional
  Moment condition_moment = Moment::Start;
  LiftedAtom atom;           // Add, Delete
  LiftedFunctionTerm target;  // Numeric
  pddl::AssignOperator assign = pddl::AssignOperator::Assign;
  LiftedExpression value;
};

struct LiftedDurationConstraint {
  pddl::Comparison comparison = pddl::Comparison::Equal;
  LiftedExpression value;
  Moment moment = Moment::Start;  // state the value is evaluated in
};

struct Parameter {
  std::string name;
  TypeId type = kNoId;
};

struct ActionSchema {
  std::string name;
  bool durative = false;
  std::vector<Parameter> parameters;
  std::uint32_t variable_slots = 0;  // parameters + every quantified variable
  // Instantaneous actions use at_start for the precondition.
  LiftedCondition at_start, over_all, at_end;
  std::vector<PrimitiveEffect> effects;
  std::vector<LiftedDurationConstraint> duration;
  // PDDL 3 preferences in the precondition or durative condition; they are
  // not part of at_start / over_all / at_end, which hold them true.
  std::vector<PreferenceCondition> preferences;
  // Set when the schema has a construct the planner cannot handle (non-linear
  // continuous change, ...): the planner and validator refuse it with this
  // message naming the construct and its position.
  std::string unsupported;
};

struct DerivedRule {
  PredicateId head = kNoId;
  std::vector<Parameter> parameters;
  std::uint32_t variable_slots = 0;
  LiftedCondition body;
};

struct TypeInfo {
  std::string name;
  std::vector<ObjectId> objects;  // every object of this type or a subtype
};

struct PredicateInfo {
  std::string name;
  std::vector<TypeId> parameter_types;
  bool derived = false;
  bool fluent = false;  // changed by an effect or a timed initial literal
};

struct FunctionInfo {
  std::string name;
  std::vector<TypeId> parameter_types;
  bool fluent = false;  // changed by an effect
};

struct GroundAtom {
  PredicateId predicate = kNoId;
  std::vector<ObjectId> args;
  bool operator==(const GroundAtom&) const = default;
};

struct NumericInitialValue {
  FunctionId function = kNoId;
  std::vector<ObjectId> args;
  double value = 0.0;
};

struct NormalizedTimedLiteral {
  double time = 0.0;
  bool positive = true;
  GroundAtom atom;
};

struct NormalizedMetric {
  bool minimize = true;
  LiftedExpression expression;
};

struct NormalizedTask {
  std::string domain_name;
  std::string problem_name;
  std::vector<std::string> objects;
  std::vector<TypeInfo> types;  // types[0] is object
  std::vector<PredicateInfo> predicates;
  std::vector<FunctionInfo> functions;
  std::vector<ActionSchema> actions;  // instantaneous and durative, in domain order
  std::vector<DerivedRule> derived_rules;
  std::vector<GroundAtom> initial_facts;
  std::vector<NumericInitialValue> initial_values;  // last value wins, as in VAL
  std::vector<NormalizedTimedLiteral> timed_literals;  // sorted by time (stable)
  LiftedCondition goal;
  std::uint32_t goal_variable_slots = 0;
  std::optional<NormalizedMetric> metric;
  // The domain has durative actions or declares :durative-actions / :time.
  bool temporal = false;
  // The domain declares :durative-actions or :time. VAL looks only at this
  // flag: without it, (total-time) is the number of steps (see validator.h).
  bool declares_time = false;
  // PDDL 3 trajectory constraints, goal preferences and preference names.
  TrajectoryConstraints pddl3;
  // Constructs the planner and validator refuse, each with its position:
  // "file:line:col: what".
  std::vector<std::string> unsupported;

  std::optional<PredicateId> find_predicate(const std::string& name) const;
  std::optional<ObjectId> find_object(const std::string& name) const;
  std::optional<std::uint32_t> find_action(const std::string& name) const;
  std::string atom_name(const GroundAtom& atom) const;
};

}  // namespace alplan
