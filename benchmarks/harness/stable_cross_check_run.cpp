// Solving the classical repair task (stable_cross_check.h), the witness that
// its minimum is the temporal one (a plan run one action at a time), and
// the cross-check of one perturbation as the stability bench asks it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>

#include "benchmarks/harness/stable_cross_check.h"
#include "planner/grounder.h"
#include "planner/planner.h"
#include "planner/search_configuration.h"
#include "planner/search_pipeline.h"
#include "planner/task_index.h"
#include "pddl_parser/writer.h"
#include "repair/reformulation.h"

namespace alplan::bench {
namespace {

// A* on LM-cut ordered by the metric: the configuration the planner says
// proves its first plan cost-optimal (proves_cost_optimal).
constexpr const char* kOptimalSearch = "complete(wastar(lmcut, w=1, order=metric, preferred=false))";

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The distance of a classical plan, read off its steps: the domain's
// actions (a durative one counted at its start half) are added steps, the
// forgo actions removed ones; keep halves and end halves are free.
struct Counted {
  std::size_t added = 0, removed = 0, kept = 0;
};

Counted count(const Plan& plan) {
  Counted c;
  for (const PlanStep& s : plan.steps) {
    if (starts_with(s.action, "xcheck-forgo-")) {
      ++c.removed;
    } else if (starts_with(s.action, "xcheck-start-keep-") || starts_with(s.action, "xcheck-keep-")) {
      ++c.kept;
    } else if (starts_with(s.action, "xcheck-start-") || !starts_with(s.action, "xcheck-")) {
      ++c.added;
    }
  }
  return c;
}

// ---- the sequential witness ----

using State = std::vector<char>;

// "" when `c` holds in `state`; otherwise what fails, or what this check
// cannot read (numbers, disjunctions).
std::string unmet(const GroundTask& task, const ConditionSet& c, const State& state) {
  if (c.never) return "a condition that never holds: " + *c.never;
  if (!c.numeric.empty() || !c.complex.empty()) return "a numeric or disjunctive condition";
  for (FactId f : c.positive) {
    if (!state[f]) return task.fact_name(f) + " is false";
  }
  for (FactId f : c.negative) {
    if (state[f]) return task.fact_name(f) + " is true";
  }
  return "";
}

std::string apply(const HappeningEffects& e, State& state) {
  if (!e.numeric.empty() || !e.conditional.empty()) return "a numeric or conditional effect";
  for (FactId f : e.del) state[f] = 0;
  for (FactId f : e.add) state[f] = 1;
  return "";
}

State after_timed_literals(const GroundTask& task) {
  State state(task.facts.size(), 0);
  for (FactId f : task.initial_facts) state[f] = 1;
  const std::vector<GroundTimedLiteral>& tils = task.timed_literals;  // sorted by time
  for (std::size_t i = 0; i < tils.size();) {
    std::size_t j = i;
    while (j < tils.size() && tils[j].time == tils[i].time) ++j;
    for (std::size_t k = i; k < j; ++k) {
      if (!tils[k].positive) state[tils[k].fact] = 0;
    }
    for (std::size_t k = i; k < j; ++k) {
      if (tils[k].positive) state[tils[k].fact] = 1;
    }
    i = j;
  }
  return state;
}

// Runs the steps in the given order, each compressed (start conditions,
// start effects, over-all and end conditions, end effects); "" when every
// step runs and the goal holds at the end.
std::string run_in_order(const GroundTask& task, const std::vector<const repair::ScheduledAction*>& order) {
  State state = after_timed_literals(task);
  for (const repair::ScheduledAction* s : order) {
    const GroundAction& a = task.actions[s->action];
    std::string why = unmet(task, a.at_start, state);
    if (why.empty()) why = apply(a.start, state);
    if (why.empty() && a.durative) {
      why = unmet(task, a.over_all, state);
      if (why.empty()) why = unmet(task, a.at_end, state);
      if (why.empty()) why = apply(a.end, state);
    }
    if (!why.empty()) return s->name + ": " + why;
  }
  const std::string goal = unmet(task, task.goal, state);
  return goal.empty() ? "" : "the goal: " + goal;
}

// The classical task has no PDDL 3 constraint or approximation, no
// continuous change and no durative action: what proof_limits can then
// name is about which snaps may share a happening, and the lock keeps every
// happening to one action.
bool only_happening_limits_can_arise(const GroundTask& task) {
  if (!task.pddl3.constraints.empty() || !task.pddl3.approximations.empty()) return false;
  return std::none_of(task.actions.begin(), task.actions.end(),
                      [](const GroundAction& a) { return a.durative || !a.continuous.empty(); });
}

// With ALPLAN_CROSS_CHECK_DUMP set to a folder, each cross-check's
// classical task and stable's plan are written there, to be checked with
// VAL or planned again where the two disagree.
void dump(const ClassicalRepairTask& task, const pddl::Problem& reformulated, const repair::ExecutingPlan& old,
          const repair::ExecutingPlan* stable_plan, double now) {
  const char* dir = std::getenv("ALPLAN_CROSS_CHECK_DUMP");
  if (!dir || !*dir) return;
  std::filesystem::create_directories(dir);
  // Named by a hash of the task: IPC instances share names (every satellite
  // problem is strips-sat-x-1), and a counter would be state kept between calls.
  const std::string text = pddl::write_problem(task.problem);
  char hash[24];
  std::snprintf(hash, sizeof hash, "%016zx", std::hash<std::string>{}(text));
  const std::string stem = std::string(dir) + "/" + hash + "-" + task.problem.name + "-at-" + std::to_string(now);
  // The keep actions name the problem's objects: in files they must be the
  // domain's constants.
  pddl::Domain domain = task.domain;
  pddl::Problem problem = task.problem;
  domain.constants.insert(domain.constants.end(), problem.objects.begin(), problem.objects.end());
  problem.objects.clear();
  std::ofstream(stem + "-domain.pddl") << pddl::write_domain(domain);
  std::ofstream(stem + "-problem.pddl") << pddl::write_problem(problem);
  std::ofstream(stem + "-temporal-problem.pddl") << pddl::write_problem(reformulated);
  std::ofstream(stem + "-old.plan") << repair::plan_text(old);
  if (stable_plan) std::ofstream(stem + "-stable.plan") << repair::plan_text(*stable_plan);
}

}  // namespace

std::string sequential_gap(const repair::ExecutingPlan& plan, double now) {
  const GroundTask& task = *plan.task;
  if (!task.axioms.empty()) return "derived predicates";
  std::vector<const repair::ScheduledAction*> order;
  for (const repair::ScheduledAction& s : plan.steps) {
    if (s.start + 1e-9 >= now) order.push_back(&s);
  }
  std::stable_sort(order.begin(), order.end(), [](const auto* a, const auto* b) { return a->start < b->start; });
  const std::string by_start = run_in_order(task, order);
  if (by_start.empty()) return "";
  std::stable_sort(order.begin(), order.end(), [](const auto* a, const auto* b) { return a->end() < b->end(); });
  if (run_in_order(task, order).empty()) return "";
  return by_start;
}

CrossCheckResult solve_classical_repair(const ClassicalRepairTask& task, double seconds) {
  const auto began = std::chrono::steady_clock::now();
  CrossCheckResult result;
  if (!task.not_comparable.empty()) {
    result.note = task.not_comparable;
    return result;
  }
  GroundingOptions grounding;  // the budget bounds grounding too
  grounding.deadline = began + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                   std::chrono::duration<double>(seconds));
  const std::shared_ptr<const GroundTask> ground_task = ground(task.domain, task.problem, grounding);
  PlannerOptions options;
  options.search = parse_search_configuration(kOptimalSearch);
  options.time_limit = std::max(0.0, seconds - since(began));
  const PlannerResult planned = Planner(ground_task, options).plan();
  // What keeps an exhausted search from being a proof (proof_limits). In
  // this task no two actions share a happening: exactly one of
  // (xcheck-free) and the mid atoms holds in every reachable state, and
  // every action reads and deletes the one that holds (a start, a copy of an
  // instantaneous action and a forgo take free; an end takes its mid), so no
  // two are applicable in one state, let alone non-mutex. The limits about
  // what a happening may hold then lose no plan. The others (PDDL 3,
  // continuous change, durations read by effects) are waived only where the
  // task shows none of them: checked on the task, not read from the text of
  // the first limit proof_limits names.
  const std::string limits = proof_limits(TaskIndex(ground_task));
  const bool moot = !limits.empty() && only_happening_limits_can_arise(*ground_task);
  const bool proves = proves_cost_optimal(options.search.engine) && (limits.empty() || moot);
  if (proves && moot) result.waived = limits;
  result.status = CrossCheckStatus::NotProven;
  if (const FoundPlan* best = planned.best()) {
    const Counted c = count(best->plan);
    result.distance = c.added + c.removed;
    result.note = std::to_string(c.kept) + " kept, " + std::to_string(c.removed) + " forgone, " +
                  std::to_string(c.added) + " new";
    const std::optional<double> cost = best->validation.metric;
    if (cost && std::abs(*cost - static_cast<double>(*result.distance)) > 1e-6) {
      result.note += "; the plan's metric is " + std::to_string(*cost) + ", not its count";
    } else if (proves) {
      result.status = CrossCheckStatus::Proven;
    }
    if (!proves) result.note += "; not a proof: " + (limits.empty() ? std::string(kOptimalSearch) : limits);
    if (!result.waived.empty()) result.note += "; waived (one action a happening): " + result.waived;
    if (proves && moot) result.note += "; the planner's limit on shared happenings does not bind (one action each)";
  } else if (planned.status == PlannerResult::Status::Unsolvable) {
    // A proof too: no repair exists at any distance.
    result.status = CrossCheckStatus::Proven;
    result.note = "proven: the classical task has no plan (" + planned.message + ")";
  } else {
    result.note = std::string(status_name(planned.status)) + " within " + std::to_string(seconds) + " s: " +
                  planned.message;
  }
  result.seconds = since(began);
  return result;
}

CrossCheckResult cross_check_stable(const repair::RepairRequest& request, const repair::ExecutingPlan* stable_plan,
                                    double seconds) {
  const auto began = std::chrono::steady_clock::now();
  // The problem as stable poses it (stable_strategy.cpp, repair): the
  // known objects, perception's additions, the observed state, the running
  // actions' ends as timed literals.
  pddl::Problem known = *request.problem;
  repair::RepairRequest seen = request;
  repair::integrate_recognized(seen, known);
  const pddl::Problem reformulated =
      repair::reformulate(*request.domain, known, seen.observed, request.in_progress, request.now);
  const ClassicalRepairTask task =
      compile_classical_repair(*request.domain, reformulated, steps_from(*request.plan, request.now),
                               !request.problem->timed_literals.empty());
  dump(task, reformulated, *request.plan, stable_plan, request.now);
  CrossCheckResult result;
  if (!task.not_comparable.empty()) {
    result.note = task.not_comparable;
  } else if (const std::string gap = stable_plan ? sequential_gap(*stable_plan, request.now) : "";
             !gap.empty()) {
    result.note = "stable's plan does not run one action at a time after the committed ends (" + gap + ")";
  } else {
    result = solve_classical_repair(task, seconds);
    if (!stable_plan) result.note += "; stable had no plan to witness the sequencing";
  }
  result.seconds = since(began);
  return result;
}

}  // namespace alplan::bench
