// stable: the repair at minimum plan distance from the old plan's remaining
// steps (Saetti & Scala, "Optimally stable plan repair", KER 2025): the
// reformulated problem compiled into a cost-optimal planning task
// (stable_compilation.h) whose plans cost their distance from the old plan.
//
// What the search guarantees. The compiled task is searched first with
// StrategyOptions::stable_proof_search, complete(wastar(H, w=1,
// order=metric)), within stable_proof_share of stable_budget:
// - ordered by the metric, f = g + w * metric->remaining(relaxed_cost, ...)
//   (best_first_search.cpp, push; search_space.cpp sets relaxed_cost =
//   value.cost) and the metric has no total-time term, so f = g + H's cost
//   estimate: with lmcut (the default) an estimate that never exceeds the
//   distance still to come (lmcut_heuristic.h), so the search is A*; with
//   blind, whose cost is 0, f = g, uniform-cost search. Nodes with the same
//   state have the same g ((total-cost) is part of the state), so an
//   admissible estimate needs no consistency for the argument below;
// - ordered by the metric, a goal is a solution only when it leaves the
//   main open list (store_evaluated keeps it in goals_; step returns it when
//   popped): A*'s test at expansion, so zero-cost keep actions cannot let a
//   dearer goal found at generation win;
// - complete: every node is goal-tested, no queue draws at random, dead ends
//   are pruned only when the sound relaxation confirms them (blind has none;
//   lmcut's are sound in either mode),
//   actions may overlap themselves, and a duplicate is dropped only for a
//   stored node with the same state -- (total-cost) included, so the same g
//   -- whose schedule allows every future its schedule allows
//   (SearchSpaceOptions, search_space.h);
// so the first plan it returns costs the minimum over the plans its search
// space holds. That space misses plans only where an exhausted complete
// search would prove nothing either (proof_limits, search_pipeline.h:
// durations read by effects, continuous change, PDDL 3); the strategy asks
// proof_limits and says "proven" only when it names nothing.
// When that search runs out of its share, the planner's own search in
// anytime mode ordered by the metric spends the rest of the budget on any
// plan and then on closer ones: its plan is "not proven minimal", and it is
// returned as it is. Taking replan's plan where it is closer would make
// stable never farther than replan by construction, and the testbed would
// compare replan with itself. Latency: up to stable_budget plus grounding
// twice (the compiled and the original task).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "repair/reformulation.h"
#include "repair/repair_strategy.h"
#include "repair/stable_compilation.h"

namespace alplan::repair {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct CompiledSearch {
  std::optional<FoundPlan> best;
  bool optimal = false;     // found by the complete search that proves (stable_proof_search)
  std::string limits;       // why optimal is no proof ("" when it is)
  std::string message;      // the planner's, when nothing was found
  int calls = 0;
};

PlannerResult plan_compiled(const std::shared_ptr<const GroundTask>& task, double now, PlannerOptions options) {
  PlanningStart start = initial_start(*task);
  start.now = now;
  return Planner(task, std::move(options)).plan_from(start);
}

CompiledSearch search_compiled(const std::shared_ptr<const GroundTask>& task, double now,
                               const StrategyOptions& options) {
  const Clock::time_point began = Clock::now();
  CompiledSearch search;
  PlannerOptions optimal = options.planner;
  optimal.search = parse_search_configuration(options.stable_proof_search);
  optimal.time_limit = std::min(options.planner.time_limit, options.stable_budget * options.stable_proof_share);
  PlannerResult result = plan_compiled(task, now, optimal);
  search.calls = 1;
  if (const FoundPlan* best = result.best()) {
    search.best = *best;
    search.optimal = proves_cost_optimal(optimal.search.engine);
    search.limits = proof_limits(TaskIndex(task));
    return search;
  }
  search.message = result.message;
  // Proven unsolvable: the compiled task has no plan, so the problem has none.
  if (result.status == PlannerResult::Status::Unsolvable) return search;
  PlannerOptions any = options.planner;
  // The planner's default first search, then weighted A* ordered by the
  // distance: its own anytime mode, whatever the repairs' search (which may
  // be anytime already, and anytime does not nest).
  any.search = parse_search_configuration(anytime_expression(alias_expression("default"), 1.0, 0, true));
  any.time_limit = std::max(0.0, std::min(options.planner.time_limit, options.stable_budget) - since(began));
  result = plan_compiled(task, now, any);
  search.calls = 2;
  if (const FoundPlan* best = result.best()) search.best = *best;
  search.message = result.message;
  return search;
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

class StableStrategy : public RepairStrategy {
 public:
  explicit StableStrategy(StrategyOptions options) : options_(std::move(options)) {}
  std::string name() const override { return "stable"; }

  RepairResult repair(const RepairRequest& request) override {
    const Clock::time_point began = Clock::now();
    pddl::Problem known = *request.problem;
    RepairRequest seen = request;
    const std::vector<RecognizedObject> integrated = integrate_recognized(seen, known);
    RepairResult result;
    result.integrated = integrated;
    result.problem = reformulate(*request.domain, known, seen.observed, request.in_progress, request.now);
    std::string why;
    try {
      repair_compiled(seen, result, why);
    } catch (const std::exception& error) {
      why = error.what();
    }
    if (!result.repaired) result = fall_back(seen, known, why, result.planner_calls, integrated);
    result.problem.init = known.init;
    result.problem.numeric_init = known.numeric_init;
    result.problem.timed_literals = known.timed_literals;
    result.seconds = since(began);
    return result;
  }

 private:
  // Plans the compilation of result.problem and fills `result` in; leaves
  // it unrepaired, saying why, when no valid plan comes of it.
  void repair_compiled(const RepairRequest& request, RepairResult& result, std::string& why) const {
    const StableCompilation compiled =
        compile_stability(*request.domain, result.problem, remaining_steps(*request.plan, request.now));
    const CompiledSearch search =
        search_compiled(ground_problem(compiled.domain, compiled.problem, nullptr), request.now, options_);
    result.planner_calls = search.calls;
    if (!search.best) {
      why = "the planner found no plan for the compiled task: " + search.message;
      return;
    }
    const std::shared_ptr<const GroundTask> task =
        ground_problem(*request.domain, result.problem, request.grounding, &result.reused_grounding);
    const MappedPlan mapped = map_back(compiled, search.best->plan);
    std::optional<ExecutingPlan> plan =
        bind_validated(task, mapped.plan, request.now, options_.planner.epsilon, why);
    if (!plan) {
      why = "the compiled plan maps to an invalid plan (" + why + ")";
      return;
    }
    const std::size_t distance = plan_distance(*request.plan, *plan, request.now);
    result.how = describe(distance, compiled.old.size(), mapped, search) + describe_remedy(*plan, request.now);
    result.proven_minimal = proven(search);
    result.plan = std::move(plan);
    result.repaired = true;
  }

  // As describe() words it: "proven minimal by" only here.
  bool proven(const CompiledSearch& search) const {
    return proves_cost_optimal(parse_search_configuration(options_.stable_proof_search).engine) && search.optimal &&
           search.limits.empty();
  }

  std::string describe(std::size_t distance, std::size_t old, const MappedPlan& mapped,
                       const CompiledSearch& search) const {
    const EngineSpec proof_search = parse_search_configuration(options_.stable_proof_search).engine;
    const std::string searched =
        proof_search.heuristic.kind == HeuristicSpec::Kind::Blind ? "uniform-cost search" : "A* on an admissible heuristic";
    std::string proof = "proven minimal by " + searched;
    if (!proves_cost_optimal(proof_search)) {
      proof = "not proven minimal: " + options_.stable_proof_search + " is not a search that proves";
    } else if (!search.optimal) {
      proof = "not proven minimal: the " + searched + " ran out of its " +
              number(options_.stable_budget * options_.stable_proof_share) + " s";
    } else if (!search.limits.empty()) {
      proof = "minimal among the plans the search represents, not proven: " + search.limits;
    }
    std::string how = "stable repair at distance " + std::to_string(distance) + " from the old plan (" + proof +
                      "): of its " + std::to_string(old) + " remaining steps " + std::to_string(mapped.kept) +
                      " kept and " + std::to_string(mapped.forgone) + " forgone, " + std::to_string(mapped.added) +
                      " new; ";
    const std::optional<double> cost = search.best->validation.metric;
    if (cost && std::abs(*cost - static_cast<double>(distance)) > 1e-6) {
      how += "the compiled plan costs " + number(*cost) + "; ";
    }
    return how;
  }

  RepairResult fall_back(const RepairRequest& request, const pddl::Problem& known, const std::string& why,
                         int calls, const std::vector<RecognizedObject>& integrated) const {
    RepairResult result = replan_from(request, *request.domain, known, options_.planner);
    result.planner_calls += calls;
    result.integrated = integrated;
    result.fallback = "replan";
    const std::string what = result.repaired ? describe_remedy(*result.plan, request.now) : result.how;
    result.how = "stable found no repair of minimum distance (" + why + "), so it fell back to replan: " + what;
    return result;
  }

  StrategyOptions options_;
};

}  // namespace

std::unique_ptr<RepairStrategy> make_stable_strategy(const StrategyOptions& options) {
  return std::make_unique<StableStrategy>(options);
}

}  // namespace alplan::repair
