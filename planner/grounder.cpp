#include "planner/grounder.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "planner/ground_trajectory.h"
#include "planner/instantiate.h"
#include "planner/reachability.h"

namespace alplan {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void collect_dependencies(const LiftedCondition& c, bool positive,
                          std::vector<std::pair<PredicateId, bool>>& out) {
  if (c.kind == LiftedCondition::Kind::Atom) out.push_back({c.atom.predicate, c.positive == positive});
  for (const LiftedCondition& child : c.children) collect_dependencies(child, positive, out);
}

bool never_applicable(const GroundAction& a) {
  return a.at_start.never || a.over_all.never || a.at_end.never;
}

void instantiate_actions(const NormalizedTask& lifted, const ReachableSet& reachable, Instantiator& instantiate,
                         GroundTask& task, Deadline deadline) {
  for (const Instantiation& i : reachable.actions) {
    deadline.check("instantiation");
    if (!lifted.actions[i.schema].unsupported.empty()) continue;
    GroundAction action = instantiate.action(i.schema, i.args);
    if (!never_applicable(action)) task.actions.push_back(std::move(action));
  }
}

void instantiate_axioms(const NormalizedTask& lifted, const ReachableSet& reachable, Instantiator& instantiate,
                        GroundTask& task, Deadline deadline) {
  const std::vector<std::uint32_t> strata = derived_strata(lifted);
  for (const Instantiation& i : reachable.axioms) {
    deadline.check("instantiation of axioms");
    const DerivedRule& rule = lifted.derived_rules[i.schema];
    std::vector<ObjectId> binding(std::max<std::size_t>(rule.variable_slots, i.args.size()), kNoId);
    std::copy(i.args.begin(), i.args.end(), binding.begin());
    ConditionSet body = instantiate.condition(rule.body, binding);
    if (body.never) continue;
    const std::optional<FactId> head = instantiate.fact({rule.head, i.args});
    task.axioms.push_back({*head, std::move(body), strata[rule.head]});
    task.strata = std::max(task.strata, strata[rule.head] + 1);
  }
  std::stable_sort(task.axioms.begin(), task.axioms.end(),
                   [](const GroundAxiom& a, const GroundAxiom& b) { return a.stratum < b.stratum; });
}

void instantiate_state(const NormalizedTask& lifted, Instantiator& instantiate, GroundTask& task) {
  for (const GroundAtom& a : lifted.initial_facts) {
    if (!lifted.predicates[a.predicate].fluent) continue;
    if (std::optional<FactId> id = task.facts.find({a.predicate, a.args})) task.initial_facts.push_back(*id);
  }
  std::sort(task.initial_facts.begin(), task.initial_facts.end());
  task.initial_facts.erase(std::unique(task.initial_facts.begin(), task.initial_facts.end()),
                           task.initial_facts.end());
  for (const NormalizedTimedLiteral& til : lifted.timed_literals) {
    if (std::optional<FactId> id = task.facts.find({til.atom.predicate, til.atom.args})) {
      task.timed_literals.push_back({til.time, *id, til.positive});
    }
  }
  std::vector<ObjectId> binding(lifted.goal_variable_slots, kNoId);
  instantiate.set_explain(true);
  task.goal = instantiate.condition(lifted.goal, binding);
  instantiate.set_explain(false);
  if (lifted.metric) {
    task.metric = GroundMetric{lifted.metric->minimize, instantiate.expression(lifted.metric->expression, {})};
  }
  // PDDL 3 as data: the validator evaluates it, the planner compiles it (pddl3_compilation.h).
  if (!lifted.pddl3.empty()) task.pddl3 = ground_trajectory(lifted, instantiate);
}

// Fluent initial values, for every numeric variable instantiation interned.
void instantiate_values(const NormalizedTask& lifted, GroundTask& task) {
  for (const NumericInitialValue& v : lifted.initial_values) {
    if (lifted.functions[v.function].fluent) task.numeric.intern({v.function, v.args});
  }
  task.initial_values.assign(task.numeric.size(), std::nan(""));
  for (const NumericInitialValue& v : lifted.initial_values) {
    if (std::optional<NumericVarId> id = task.numeric.find({v.function, v.args})) task.initial_values[*id] = v.value;
  }
}

}  // namespace

std::vector<std::uint32_t> derived_strata(const NormalizedTask& task) {
  std::vector<std::uint32_t> stratum(task.predicates.size(), 0);
  const std::uint32_t limit = static_cast<std::uint32_t>(task.predicates.size()) + 1;
  bool changed = true;
  while (changed) {
    changed = false;
    for (const DerivedRule& rule : task.derived_rules) {
      std::vector<std::pair<PredicateId, bool>> dependencies;
      collect_dependencies(rule.body, true, dependencies);
      for (const auto& [predicate, positive] : dependencies) {
        if (!task.predicates[predicate].derived) continue;
        const std::uint32_t needed = stratum[predicate] + (positive ? 0 : 1);
        if (stratum[rule.head] < needed) {
          stratum[rule.head] = needed;
          changed = true;
          if (needed > limit) {
            throw GroundingError("the derived predicate " + task.predicates[rule.head].name +
                                 " depends on its own negation: the axioms are not stratifiable");
          }
        }
      }
    }
  }
  return stratum;
}

namespace {

std::shared_ptr<GroundTask> build(std::shared_ptr<const NormalizedTask> lifted, const ReachableSet& reachable,
                                  const GroundingOptions& options) {
  auto task = std::make_shared<GroundTask>();
  task->lifted = lifted;

  // The fact table holds the reachable fluent atoms, in discovery order.
  for (std::uint32_t a = 0; a < reachable.atoms.size(); ++a) {
    const GroundKey& key = reachable.atoms.key(a);
    if (lifted->predicates[key.head].fluent) task->facts.intern(key);
  }
  const StaticFacts statics = StaticFacts::of(*lifted);
  Instantiator instantiate(*lifted, statics, task->facts, task->numeric, {true, false});
  instantiate.set_ghosts(&task->ghosts);

  Clock::time_point start = Clock::now();
  instantiate_actions(*lifted, reachable, instantiate, *task, Deadline(options.deadline));
  instantiate_state(*lifted, instantiate, *task);
  task->times.instantiate = seconds_since(start);

  start = Clock::now();
  instantiate_axioms(*lifted, reachable, instantiate, *task, Deadline(options.deadline));
  task->times.axioms = seconds_since(start);
  instantiate_values(*lifted, *task);
  return task;
}

std::shared_ptr<GroundTask> build(std::shared_ptr<const NormalizedTask> lifted, const GroundingOptions& options) {
  const Clock::time_point start = Clock::now();
  ReachabilityOptions reachability;
  reachability.deadline = options.deadline;
  const ReachableSet reachable = compute_reachable(*lifted, reachability);
  const double reachability_time = seconds_since(start);
  std::shared_ptr<GroundTask> task = build(std::move(lifted), reachable, options);
  task->times.reachability = reachability_time;
  return task;
}

}  // namespace

std::shared_ptr<const GroundTask> ground(std::shared_ptr<const NormalizedTask> lifted,
                                         const GroundingOptions& options) {
  return build(std::move(lifted), options);
}

std::shared_ptr<GroundTask> ground_reachable(std::shared_ptr<const NormalizedTask> lifted,
                                             const ReachableSet& reachable, const GroundingOptions& options) {
  return build(std::move(lifted), reachable, options);
}

std::shared_ptr<const GroundTask> ground(const pddl::Domain& domain, const pddl::Problem& problem,
                                         const GroundingOptions& options) {
  const Clock::time_point start = Clock::now();
  auto lifted = std::make_shared<const NormalizedTask>(normalize(domain, problem, options.names));
  const double normalize_time = seconds_since(start);
  std::shared_ptr<GroundTask> task = build(std::move(lifted), options);
  task->times.normalize = normalize_time;
  return task;
}

}  // namespace alplan
