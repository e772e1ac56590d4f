// Internal to normalisation: name tables and the conversion of conditions,
// expressions and effects with a scope of variables.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/normalized_task.h"

namespace alplan::detail {

struct NameTables {
  std::unordered_map<std::string, ObjectId> objects;
  std::unordered_map<std::string, PredicateId> predicates;
  std::unordered_map<std::string, FunctionId> functions;
  std::unordered_map<std::string, TypeId> types;  // also "(either a b)" unions
  std::unordered_map<std::string, std::uint32_t> preferences;
};

// Variables visible at a point of a formula: name -> slot.
class VariableScope {
 public:
  std::uint32_t bind(const std::string& name);
  void unbind(std::size_t count) { bound_.resize(bound_.size() - count); }
  std::uint32_t slot_of(const std::string& name) const;
  std::uint32_t slots_used() const { return next_slot_; }

 private:
  std::vector<std::pair<std::string, std::uint32_t>> bound_;
  std::uint32_t next_slot_ = 0;
};

class FormulaConverter {
 public:
  FormulaConverter(NormalizedTask& task, NameTables& names, std::string file)
      : task_(task), names_(names), file_(std::move(file)) {}

  LiftedCondition condition(const pddl::Condition& c, VariableScope& scope, bool negated = false);
  // The parts of a durative condition that hold at `time`.
  LiftedCondition timed_part(const pddl::Condition& c, pddl::TimeSpecifier time, VariableScope& scope);
  LiftedExpression expression(const pddl::NumericExpression& e, const VariableScope& scope);
  void effects(const pddl::Effect& e, bool durative, VariableScope& scope, ActionSchema& schema);
  LiftedAtom atom(const pddl::Atom& a, const VariableScope& scope);
  TypeId type_of(const pddl::TypeNames& types);
  std::string where(pddl::SourceLocation location) const;
  // Constructs met since the last call that the planner cannot handle.
  std::vector<std::string> take_unsupported() { return std::move(unsupported_); }
  // Preferences met in conditions since the last call (the goal's, an action's).
  std::vector<PreferenceCondition> take_preferences() { return std::move(preferences_); }
  // A :constraints section into task.pddl3.constraints (normalize_constraints.cpp).
  void constraints(const pddl::Condition& c);

 private:
  struct EffectContext;
  void effect(const pddl::Effect& e, EffectContext& context, VariableScope& scope, ActionSchema& schema);
  // An untimed numeric effect of a durative action: continuous change.
  // False (and the reason recorded as unsupported) unless it is linear.
  bool continuous(const pddl::Effect& e, const EffectContext& context, const VariableScope& scope, PrimitiveEffect& p);
  std::vector<QuantifiedVariable> bind_all(const std::vector<pddl::TypedName>& variables, VariableScope& scope);
  LiftedTerm term(const pddl::Term& t, const VariableScope& scope);
  void unsupported(pddl::SourceLocation location, const std::string& what);
  // The index of a preference name, added on first mention.
  std::uint32_t preference_id(const std::string& name);
  // Records a PDDL 3 construct for the planner's refusal.
  void pddl3_use(pddl::SourceLocation location, const std::string& what);
  void preference(const pddl::Condition& c, VariableScope& scope, bool negated);
  struct ConstraintContext;
  void constraint(const pddl::Condition& c, VariableScope& scope, ConstraintContext& context);
  void add_constraint(const pddl::Condition& c, VariableScope& scope, const ConstraintContext& context);

  NormalizedTask& task_;
  NameTables& names_;
  std::string file_;
  std::vector<std::string> unsupported_;
  // Universal quantifiers enclosing the condition being converted, where a
  // preference may stand (a conjunctive context); and whether it is one.
  std::vector<QuantifiedVariable> enclosing_;
  int disjunctive_depth_ = 0;
  pddl::TimeSpecifier current_time_ = pddl::TimeSpecifier::AtStart;
  std::vector<PreferenceCondition> preferences_;
};

LiftedCondition make_and(std::vector<LiftedCondition> children);
LiftedCondition make_or(std::vector<LiftedCondition> children);

}  // namespace alplan::detail
