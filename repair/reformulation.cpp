#include "repair/reformulation.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <set>

#include "planner/grounder.h"

namespace alplan::repair {

std::optional<std::string> object_type(const pddl::Problem& problem, const std::string& object) {
  for (const pddl::TypedName& o : problem.objects) {
    if (o.name == object) return o.types.empty() ? std::string("object") : o.types.front();
  }
  return std::nullopt;
}

namespace {

// The believed states as the planner's, on the task's ids.
std::vector<ObservedState> observed_history(const GroundTask& task, const std::vector<WorldState>& history) {
  const StateMapping mapping(task);
  std::vector<ObservedState> out;
  for (const WorldState& w : history) {
    const ExplicitState state = mapping.to_explicit(w);
    ObservedState o;
    o.time = w.time;
    for (FactId f = 0; f < task.facts.size(); ++f) {
      if (state.fact(f)) o.facts.push_back(f);
    }
    for (NumericVarId v = 0; v < task.numeric.size(); ++v) o.values.push_back(state.value(v));
    out.push_back(std::move(o));
  }
  return out;
}

}  // namespace

void shift_constraint_times(pddl::Condition& c, double shift) {
  using Kind = pddl::Condition::Kind;
  if (c.kind == Kind::Within || c.kind == Kind::HoldDuring || c.kind == Kind::HoldAfter) {
    for (double& t : c.numbers) t -= shift;
  }
  for (pddl::Condition& child : c.children) shift_constraint_times(child, shift);
}

pddl::Problem reformulate(const pddl::Domain& domain, const pddl::Problem& base, const WorldState& observed,
                          const std::vector<ActionInProgress>& in_progress, double now, double shift) {
  // The frame alone: the base's initial state and timed literals are
  // replaced, so copying them (hundreds of atoms) would be wasted.
  pddl::Problem problem;
  problem.name = base.name;
  problem.domain_name = base.domain_name;
  problem.domain_name_location = base.domain_name_location;
  problem.requirements = base.requirements;
  problem.objects = base.objects;
  problem.goal = base.goal;
  problem.constraints = base.constraints;
  if (problem.constraints && shift != 0.0) shift_constraint_times(*problem.constraints, shift);
  problem.metric = base.metric;
  problem.location = base.location;
  std::set<std::string> names;
  for (const pddl::TypedName& o : base.objects) names.insert(o.name);
  for (const pddl::TypedName& c : domain.constants) names.insert(c.name);
  std::set<std::string> predicates, functions;
  for (const pddl::PredicateDeclaration& p : domain.predicates) predicates.insert(p.name);
  for (const pddl::FunctionDeclaration& f : domain.functions) functions.insert(f.name);
  // Only what the problem can name: the world also holds atoms about objects
  // perception has not recognised yet.
  auto known = [&](const AtomKey& key, const std::set<std::string>& heads) {
    if (!heads.count(key.front())) return false;
    for (std::size_t i = 1; i < key.size(); ++i) {
      if (!names.count(key[i])) return false;
    }
    return true;
  };
  for (const AtomKey& a : observed.atoms) {
    if (known(a, predicates)) problem.init.push_back(atom_of(a));
  }
  // A value an action underway changes continuously (a robot mid-move
  // drains its battery) starts the new plan at what it will be when that
  // action ends: the action cannot be stopped, and the new plan can move the
  // robot only after it arrives, so for a drain this is the level the plan
  // has to work with (and for a charge, what it will have).
  std::map<AtomKey, double> values = observed.values;
  for (const ActionInProgress& a : in_progress) {
    for (const auto& [key, rate] : a.rates) values[key] += rate * std::max(0.0, a.expected_end - now);
  }
  for (const auto& [key, value] : values) {
    if (!known(key, functions)) continue;
    pddl::NumericFact f;
    f.function = atom_of(key);
    f.value = value;
    problem.numeric_init.push_back(f);
  }
  for (const pddl::TimedInitialLiteral& til : base.timed_literals) {
    if (til.time <= now) continue;  // already happened; the world shows it
    pddl::TimedInitialLiteral shifted = til;
    shifted.time -= shift;
    problem.timed_literals.push_back(shifted);
  }
  for (const ActionInProgress& a : in_progress) {
    const double at = std::max(a.expected_end, now) - shift;
    for (const auto* list : {&a.dels, &a.adds}) {
      for (const AtomKey& k : *list) {
        if (!known(k, predicates)) continue;
        pddl::TimedInitialLiteral til;
        til.time = at;
        til.positive = list == &a.adds;
        til.atom = atom_of(k);
        problem.timed_literals.push_back(til);
      }
    }
  }
  return problem;
}

std::shared_ptr<const GroundTask> ground_problem(const pddl::Domain& domain, const pddl::Problem& problem,
                                                 GroundingCache* cache, bool* reused) {
  std::shared_ptr<const GroundTask> task = cache ? cache->ground(domain, problem) : ground(domain, problem);
  if (reused) *reused = cache && cache->last_reused();
  return task;
}

std::shared_ptr<const GroundTask> without_schemas(std::shared_ptr<const GroundTask> task,
                                                  const std::set<std::string>& excluded) {
  const auto forbidden = [&](const GroundAction& a) { return excluded.count(task->lifted->actions[a.schema].name) != 0; };
  if (std::none_of(task->actions.begin(), task->actions.end(), forbidden)) return task;
  auto view = std::make_shared<GroundTask>(*task);
  std::erase_if(view->actions.mutate(), forbidden);
  return view;
}

std::string no_plan_reason(PlannerResult::Status status, const std::string& message) {
  static const std::string kPrefix = "no plan exists: ";
  if (status == PlannerResult::Status::Unsolvable) {
    const std::string proof = message.rfind(kPrefix, 0) == 0 ? message.substr(kPrefix.size()) : message;
    return "no plan reaches the goal from the observed state with the objects known now (proved for that task: " +
           proof + "); something perception has not seen yet may still change it";
  }
  if (status == PlannerResult::Status::LimitReached || status == PlannerResult::Status::Exhausted) {
    return "the planner found no plan from the observed state (not a proof: " + message + ")";
  }
  return "the planner found no plan from the observed state: " + message;
}

PlanningOutcome plan_in_process(const pddl::Domain& domain, const pddl::Problem& problem, double now,
                                const PlannerOptions& options, GroundingCache* cache,
                                const std::set<std::string>& excluded, const std::vector<WorldState>* history) {
  const auto began = std::chrono::steady_clock::now();
  PlanningOutcome outcome;
  std::shared_ptr<const GroundTask> task;
  try {
    task = without_schemas(ground_problem(domain, problem, cache, &outcome.reused_grounding), excluded);
  } catch (const std::exception& error) {
    outcome.status = PlannerResult::Status::Unsupported;
    outcome.message = std::string("cannot ground the reformulated problem: ") + error.what();
    return outcome;
  }
  PlanningStart start = initial_start(*task);
  start.now = now;
  if (history && !task->pddl3.constraints.empty()) start.history = observed_history(*task, *history);
  PlannerResult result = Planner(task, options, cache ? cache->planner_workspace() : nullptr).plan_from(start);
  outcome.status = result.status;
  outcome.message = result.message;
  if (const FoundPlan* best = result.best()) outcome.plan = bind_plan(task, best->plan, options.epsilon);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return outcome;
}

}  // namespace alplan::repair
