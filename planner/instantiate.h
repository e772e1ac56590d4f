// Instantiation of lifted conditions, expressions, effects and action schemas
// under a binding of variable slots to objects, with simplification: equality
// is decided, quantifiers are expanded over their (finite) types, static
// atoms and static numeric terms are replaced by their values, and what
// remains is flattened into ConditionSets.
#pragma once

#include <functional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "planner/fact_table.h"
#include "planner/ground_task.h"
#include "planner/normalized_task.h"

namespace alplan {

// What never changes: the initial facts of static predicates and the initial
// values of static functions.
struct StaticFacts {
  std::unordered_set<GroundKey, GroundKeyHash> true_atoms;
  std::unordered_map<GroundKey, double, GroundKeyHash> values;

  static StaticFacts of(const NormalizedTask& task);
};

struct InstantiationOptions {
  // Replace static atoms by true/false (the planner); the validator keeps
  // them as facts so that a violation can name them.
  bool simplify_static = true;
  // Intern atoms not yet in the fact table (the validator); otherwise an
  // unknown fluent atom is unreachable and a positive literal on it is false.
  bool intern_unknown = false;
  // Record, for a condition that can never hold, which part fails (the
  // validator reports it; the grounder just drops the action).
  bool explain = false;
};

class Instantiator {
 public:
  Instantiator(const NormalizedTask& task, const StaticFacts& statics, GroundKeyTable& facts,
               GroundKeyTable& numeric, InstantiationOptions options);

  const NormalizedTask& task() const { return task_; }
  GroundAction action(std::uint32_t schema, const std::vector<ObjectId>& args);
  // The goal is instantiated once, so it always says why it cannot hold.
  void set_explain(bool on) { options_.explain = on; }
  ConditionSet condition(const LiftedCondition& condition, std::vector<ObjectId>& binding);
  // A preference's condition: with what it names recorded even where it can
  // never hold (ConditionSet::mentioned, ghost_mentioned), as VAL's mutex
  // rule reads a preference's atoms whatever its value.
  ConditionSet preference_condition(const LiftedCondition& condition, std::vector<ObjectId>& binding);
  GroundFormula formula(const LiftedCondition& condition, std::vector<ObjectId>& binding);
  GroundExpression expression(const LiftedExpression& expression, const std::vector<ObjectId>& binding);
  // The id of a ground atom if it is (or, when interning, becomes) a fact.
  std::optional<FactId> fact(const GroundKey& key);
  // Where atoms that are no fact but are deleted or named get their ids
  // (ConditionSet::ghost_mentioned); null: nowhere (they are dropped).
  void set_ghosts(GroundKeyTable* ghosts) { ghosts_ = ghosts; }

 private:
  void effects(const ActionSchema& schema, std::vector<ObjectId>& binding, GroundAction& action);
  void primitive(const PrimitiveEffect& effect, std::vector<ObjectId>& binding, std::size_t forall_index,
                 GroundAction& action);
  GroundKey key(const LiftedAtom& atom, const std::vector<ObjectId>& binding) const;
  GroundKey key(const LiftedFunctionTerm& term, const std::vector<ObjectId>& binding) const;
  // Fills the reusable scratch key: lookups then allocate nothing.
  const GroundKey& scratch(std::uint32_t head, const std::vector<LiftedTerm>& args,
                           const std::vector<ObjectId>& binding);
  std::string name(const GroundKey& key, bool function) const;
  // Every fluent fact the condition names, quantifiers expanded.
  void mentioned_facts(const LiftedCondition& condition, std::vector<ObjectId>& binding, std::vector<FactId>& out,
                       std::vector<std::uint32_t>& ghosts);
  // Fills set.mentioned (ground_task.h) for one of an action's conditions.
  // `even_never`: also where the condition can never hold.
  void add_mentions(const LiftedCondition& condition, std::vector<ObjectId>& binding, ConditionSet& set,
                    bool even_never = false);

  const NormalizedTask& task_;
  GroundKeyTable* ghosts_ = nullptr;
  const StaticFacts& statics_;
  GroundKeyTable& facts_;
  GroundKeyTable& numeric_;
  InstantiationOptions options_;
  GroundKey scratch_;
};

// Flattens a formula: top-level conjunctions of literals and comparisons go
// to the lists, anything else stays a complex formula.
ConditionSet flatten(GroundFormula formula);

// Calls `visit` once per binding of `variables` (their slots set in
// `binding`), in order of the types' objects, the first variable slowest.
void for_each_binding(const NormalizedTask& task, const std::vector<QuantifiedVariable>& variables,
                      std::vector<ObjectId>& binding, const std::function<void()>& visit);

// The ground instances of a goal's or action's preferences under `binding`
// (an action's arguments, or the goal's empty binding).
std::vector<GroundPreference> ground_preferences(const std::vector<PreferenceCondition>& preferences,
                                                 std::vector<ObjectId> binding, Instantiator& instantiate);

}  // namespace alplan
