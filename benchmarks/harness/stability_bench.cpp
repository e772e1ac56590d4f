#include "benchmarks/harness/stability_bench.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "benchmarks/harness/stable_cross_check.h"
#include "benchmarks/harness/table.h"
#include "domains/pddl_files.h"
#include "planner/grounder.h"
#include "planner/normalize.h"
#include "planner/planner.h"
#include "planner/validator.h"
#include "repair/reformulation.h"
#include "repair/world_simulator.h"

namespace alplan::bench {
namespace {

using repair::ExecutingPlan;
using repair::ScheduledAction;

struct Instance {
  std::string domain_name;
  int number = 0;
  domains::LoadedFiles files;
  std::shared_ptr<const GroundTask> task;  // reachable from the initial state
  ExecutingPlan plan;                      // the planner's, bound to `task`
  ExecutingPlan full;                      // the same, every condition kept
};

// Where the execution stands when the world changes.
struct Cut {
  double now = 0.0;
  repair::WorldState state;
  std::vector<repair::ActionInProgress> running;
};

// Runs the plan's snaps before `now` in the simulated world: starts of
// steps that began, ends of those that ended.
Cut execute_until(const Instance& instance, double now) {
  repair::WorldSimulator world(repair::initial_world(*instance.files.problem),
                               repair::timed_literal_events(*instance.files.problem));
  struct Snap {
    double time;
    bool start;
    const ScheduledAction* step;
  };
  std::vector<Snap> snaps;
  for (const ScheduledAction& s : instance.plan.steps) {
    if (s.start + 1e-9 >= now) continue;
    snaps.push_back({s.start, true, &s});
    if (instance.plan.task->actions[s.action].durative && s.end() + 1e-9 < now) {
      snaps.push_back({s.end(), false, &s});
    }
  }
  std::stable_sort(snaps.begin(), snaps.end(), [](const Snap& a, const Snap& b) { return a.time < b.time; });
  for (const Snap& snap : snaps) {
    world.advance(snap.time);
    if (snap.start) {
      world.start_action(*instance.plan.task, snap.step->action, snap.time, snap.step->duration);
    } else {
      world.end_action(*instance.plan.task, snap.step->action, snap.time);
    }
  }
  world.advance(now);
  // The plan is valid and nothing perturbs the world before `now`, so every
  // step must have done what it says; a void one would make the cut a lie.
  if (!world.void_actions().empty()) {
    const repair::VoidAction& v = world.void_actions().front();
    throw std::logic_error("the plan's own execution failed in the simulated world at " + std::to_string(v.time) +
                           ": " + v.action + ": " + v.why);
  }
  Cut cut;
  cut.now = now;
  cut.state = world.observe();
  cut.running = world.in_progress();
  return cut;
}

// The problem as the perturbed state poses it (running actions' ends as
// timed literals, repair/reformulation.h), normalised once per perturbation:
// the old plan's rest and every strategy's plan are validated against it.
std::shared_ptr<const NormalizedTask> observed_task(const pddl::Domain& domain, const pddl::Problem& problem,
                                                   const Cut& cut) {
  const pddl::Problem observed = repair::reformulate(domain, problem, cut.state, cut.running, cut.now);
  return std::make_shared<const NormalizedTask>(normalize(domain, observed));
}

ValidationResult validate_on(const std::shared_ptr<const NormalizedTask>& task, const Plan& plan, double epsilon) {
  PlanValidator validator(task, ValidatorOptions{epsilon, false});
  return validator.validate(plan);
}

// Whether the goal survives the grounding's reachability analysis from the
// perturbed state. A perturbation after which it does not (a hoist lost
// where no other reaches the crate) leaves no plan for any strategy to find,
// and that is proven, not a failure of a strategy: Fox et al. compare
// repairs of problems that have them.
bool goal_reachable(const std::shared_ptr<const NormalizedTask>& task) { return !ground(task)->goal.never; }

Plan remaining(const ExecutingPlan& plan, double now) {
  Plan steps = repair::steps_of(plan);
  std::erase_if(steps.steps, [&](const PlanStep& s) { return s.time.value_or(0.0) + 1e-9 < now; });
  return steps;
}

std::vector<std::string> busy_objects(const std::vector<repair::ActionInProgress>& running) {
  std::vector<std::string> busy;
  for (const repair::ActionInProgress& a : running) {
    std::istringstream words(a.name.substr(1, a.name.size() - 2));
    std::string word;
    words >> word;  // the schema
    while (words >> word) busy.push_back(word);
  }
  return busy;
}

std::optional<Instance> prepare(const StabilityBenchOptions& options, const std::string& domain, int number,
                                std::string& why) {
  Instance instance;
  instance.domain_name = std::filesystem::path(domain).filename().string();
  instance.number = number;
  const std::string dir = options.ipc_dir + "/" + domain;
  instance.files = domains::load_pddl(dir + "/domain.pddl", dir + "/instances/instance-" + std::to_string(number) + ".pddl");
  instance.task = ground(*instance.files.domain, *instance.files.problem);
  // The first plan comes from the planner's default search whatever the
  // repairs search with: the runs of one problem start from the same plan.
  PlannerOptions planner = repair::executing_planner_options();
  planner.epsilon = options.strategy.planner.epsilon;
  planner.time_limit = options.plan_seconds;
  const PlannerResult planned = Planner(instance.task, planner).plan();
  const FoundPlan* best = planned.best();
  if (!best) {
    why = "no plan within " + fixed(options.plan_seconds, 0) + " s: " + planned.message;
    return std::nullopt;
  }
  instance.plan = repair::bind_plan(instance.task, best->plan, planner.epsilon);
  instance.full = repair::with_all_conditions(instance.plan);
  return instance;
}

// One perturbation that breaks the rest of the plan, with the state it
// leaves and the old plan's failure there; nothing after `draws` tries.
struct Perturbed {
  Perturbation perturbation;
  Cut cut;
  pddl::Problem problem;  // the goals added
  std::shared_ptr<const NormalizedTask> observed;  // observed_task of the two
  Violation failure;
};

std::optional<Perturbed> draw_breaking(const Instance& instance, PerturbationKind kind, int draws, double epsilon,
                                       std::mt19937_64& random, int& offered) {
  const std::vector<repair::AtomKey> goals = goal_atoms(*instance.files.problem);
  const std::vector<ScheduledAction>& steps = instance.plan.steps;
  for (int attempt = 0; attempt < draws; ++attempt) {
    const double now = steps[std::uniform_int_distribution<std::size_t>(0, steps.size() - 1)(random)].start;
    Perturbed p;
    p.cut = execute_until(instance, now);
    PerturbationContext context{&p.cut.state, &instance.full, now, instance.task.get(), goals,
                                busy_objects(p.cut.running)};
    std::optional<Perturbation> drawn = draw_perturbation(kind, context, random);
    if (!drawn) continue;
    ++offered;
    for (const auto& [atom, value] : drawn->changes) p.cut.state.set(atom, value);
    p.problem = with_goals(*instance.files.problem, drawn->added_goals);
    p.observed = observed_task(*instance.files.domain, p.problem, p.cut);
    const ValidationResult old = validate_on(p.observed, remaining(instance.plan, now), epsilon);
    if (old.valid || !goal_reachable(p.observed)) continue;
    p.failure = old.violation.value_or(Violation{});
    p.perturbation = std::move(*drawn);
    return p;
  }
  return std::nullopt;
}

std::size_t remaining_count(const ExecutingPlan& plan, double now) {
  return static_cast<std::size_t>(std::count_if(plan.steps.begin(), plan.steps.end(),
                                                [&](const ScheduledAction& s) { return s.start + 1e-9 >= now; }));
}

double makespan(const ExecutingPlan& plan, const Cut& cut) {
  double end = cut.now;
  for (const ScheduledAction& s : plan.steps) end = std::max(end, s.end());
  for (const repair::ActionInProgress& a : cut.running) end = std::max(end, a.expected_end);
  return end;
}

// The first step from `now` on, by time and then name: the step an
// executive would dispatch next.
std::string first_step(const ExecutingPlan& plan, double now) {
  const ScheduledAction* first = nullptr;
  for (const ScheduledAction& s : plan.steps) {
    if (s.start + 1e-9 < now) continue;
    if (!first || s.start < first->start - 1e-9 || (s.start < first->start + 1e-9 && s.name < first->name)) first = &s;
  }
  return first ? first->name : "";
}

void measure(StabilityRun& run, const repair::RepairResult& result, const Instance& instance, const Perturbed& p,
             double epsilon) {
  run.repaired = result.repaired && result.plan;
  run.seconds = result.seconds;
  run.planner_calls = result.planner_calls;
  run.fallback = result.fallback;
  run.how = result.how;
  run.proven = result.proven_minimal;
  if (!run.repaired) return;
  const ExecutingPlan& plan = *result.plan;
  run.valid = validate_on(p.observed, remaining(plan, p.cut.now), epsilon).valid;
  run.new_steps = remaining_count(plan, p.cut.now);
  run.distance = repair::plan_distance(instance.plan, plan, p.cut.now);
  // |new \ old| - |old \ new| = |new| - |old|, so the distance's two parts
  // follow from it and the two lengths.
  const auto shared = static_cast<std::ptrdiff_t>(run.new_steps + run.old_remaining) -
                      static_cast<std::ptrdiff_t>(run.distance);
  run.added = run.new_steps - static_cast<std::size_t>(shared / 2);
  run.removed = run.old_remaining - static_cast<std::size_t>(shared / 2);
  run.same_first = first_step(plan, p.cut.now) == first_step(instance.plan, p.cut.now);
  run.makespan = makespan(plan, p.cut);
}

repair::RepairRequest request_for(const Instance& instance, const Perturbed& p) {
  repair::RepairRequest request;
  request.domain = instance.files.domain.get();
  request.problem = &p.problem;
  request.plan = &instance.plan;
  request.failure = &p.failure;
  request.observed = p.cut.state;
  request.in_progress = p.cut.running;
  request.now = p.cut.now;
  return request;
}

// Every strategy on the perturbation; returns stable's plan, when it made
// one, for the cross-check.
std::optional<ExecutingPlan> run_strategies(const StabilityBenchOptions& options, const Instance& instance,
                                            const Perturbed& p, StabilityRun base, std::vector<StabilityRun>& out) {
  std::optional<ExecutingPlan> stable_plan;
  for (const std::string& name : options.strategies) {
    StabilityRun run = base;
    run.strategy = name;
    try {
      const repair::RepairRequest request = request_for(instance, p);
      const repair::RepairResult result = repair::make_strategy(name, options.strategy)->repair(request);
      measure(run, result, instance, p, options.strategy.planner.epsilon);
      if (name == "stable" && result.repaired) stable_plan = result.plan;
    } catch (const std::exception& error) {
      run.how = std::string("the strategy threw: ") + error.what();
    }
    out.push_back(std::move(run));
  }
  return stable_plan;
}

// The cross-check of stable's distance (stable_cross_check.h), recorded on
// each of the perturbation's runs (the `first` on).
void cross_check(const StabilityBenchOptions& options, const Instance& instance, const Perturbed& p,
                 const ExecutingPlan* stable_plan, std::vector<StabilityRun>& runs, std::size_t first) {
  CrossCheckResult check;
  try {
    check = cross_check_stable(request_for(instance, p), stable_plan, options.cross_check_seconds);
  } catch (const std::exception& error) {
    check.status = CrossCheckStatus::NotProven;
    check.note = std::string("the cross-check threw: ") + error.what();
  }
  for (std::size_t i = first; i < runs.size(); ++i) {
    runs[i].cross_check_status = to_string(check.status);
    runs[i].cross_check_distance = check.distance;
    runs[i].cross_check_note = check.note;
    runs[i].cross_check_seconds = check.seconds;
  }
}

void run_instance(const StabilityBenchOptions& options, const Instance& instance, StabilityBenchResult& result) {
  for (PerturbationKind kind : options.kinds) {
    for (int k = 0; k < options.perturbations; ++k) {
      // A seed per run, from the options' and the run's place: runs can be
      // repeated one by one.
      std::seed_seq seq{static_cast<std::uint32_t>(options.seed), static_cast<std::uint32_t>(instance.number),
                        static_cast<std::uint32_t>(kind), static_cast<std::uint32_t>(k),
                        static_cast<std::uint32_t>(std::hash<std::string>{}(instance.domain_name))};
      std::mt19937_64 random(seq);
      const std::string where = instance.domain_name + " " + std::to_string(instance.number) + " " + to_string(kind) +
                                " " + std::to_string(k);
      int offered = 0;
      const std::optional<Perturbed> p =
          draw_breaking(instance, kind, options.draws, options.strategy.planner.epsilon, random, offered);
      if (!p) {
        result.skipped.push_back(where + ": " + std::to_string(options.draws) + " draws, " + std::to_string(offered) +
                                 " perturbations offered, none broke the rest of the plan and left the goal reachable");
        continue;
      }
      StabilityRun base;
      base.domain = instance.domain_name;
      base.problem = instance.number;
      base.perturbation = k;
      base.kind = to_string(kind);
      base.description = p->perturbation.description;
      base.cut = p->cut.now;
      base.old_remaining = remaining_count(instance.plan, p->cut.now);
      base.old_makespan = makespan(instance.plan, p->cut);
      const std::size_t first = result.runs.size();
      const std::optional<ExecutingPlan> stable_plan = run_strategies(options, instance, *p, base, result.runs);
      if (options.cross_check) {
        cross_check(options, instance, *p, stable_plan ? &*stable_plan : nullptr, result.runs, first);
      }
      if (!options.progress) continue;
      *options.progress << "stability: " << where << ": " << base.description;
      if (options.cross_check) {
        const StabilityRun& checked = result.runs.back();
        *options.progress << " [cross-check " << checked.cross_check_status
                          << (checked.cross_check_distance ? " " + std::to_string(*checked.cross_check_distance) : "")
                          << ", " << fixed(checked.cross_check_seconds, 1) << " s]";
      }
      *options.progress << "\n";
    }
  }
}

}  // namespace

StabilityBenchResult run_stability_bench(const StabilityBenchOptions& options) {
  StabilityBenchResult result;
  for (const std::string& domain : options.domains) {
    for (int number = options.first_problem; number <= options.last_problem; ++number) {
      std::string why;
      std::optional<Instance> instance;
      try {
        instance = prepare(options, domain, number, why);
      } catch (const std::exception& error) {
        why = error.what();
      }
      if (!instance) {
        result.skipped.push_back(domain + " " + std::to_string(number) + ": " + why);
        continue;
      }
      run_instance(options, *instance, result);
    }
  }
  return result;
}

}  // namespace alplan::bench
