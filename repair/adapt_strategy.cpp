// adapt: plan adaptation with LPG-ADAPT's objective (Gerevini & Serina
// 2000; Fox, Gerevini, Long & Serina, "Plan stability: replanning versus
// plan repair", ICAPS 2006): among plans from the observed state, minimise
// the problem's metric (the makespan where it has none) plus adapt_penalty
// times the plan distance D(O, pi) = |pi \ O| + |O \ pi| from the old plan's
// remaining steps O, over multisets of ground actions -- steps added and
// steps removed both count, a repeated action once per occurrence -- under
// a budget of adapt_budget seconds of search.
//
// How. The reformulated problem is compiled as `stable` compiles it
// (stable_compilation.h, Saetti & Scala's compilation), with the distance
// counted apart from the domain's costs (DistanceCounter::Apart): per old
// step a keep action (the step itself, distance 0) and a forgo action
// (distance 1), every other action distance 1, in (alplan-distance); the
// compiled metric is the problem's own plus adapt_penalty * (alplan-distance),
// so the home domains' (+ (total-time) (total-cost)) keeps its action costs.
// The planner's anytime search runs on it for adapt_budget seconds: the
// repairs' own first search finds a plan, then weighted A* with weights 5,
// 3 down to adapt_min_weight (adapt_expansions each), ordered by that
// metric and guided by landmark cuts (compiled_search says why), looks for
// better ones. The best plan maps back (keep -> the old step, forgo ->
// dropped), is bound to the reformulated task and validated there from now.
//
// What it is: LPG-ADAPT's objective, added plus removed actions, traded
// against plan quality under a time budget, and "seeded" with the old plan
// only in that the old plan's steps are actions of the compiled task that
// cost no distance. What it is not: LPG's local search in the space of
// action graphs, which starts from the old plan itself and repairs its
// inconsistencies; nor `stable`, which minimises the distance alone and
// proves it minimal when its complete search ends. Grounding the compiled
// task (no grounding cache fits it) comes on top of the budget.
//
// Without a plan in the budget adapt reports no repair (the planner's
// reason). When the compilation cannot be made or planned (a domain naming
// something alplan-..., an old step the domain cannot take) or its plan
// does not map to a valid one, adapt replans under the same budget and
// names `replan` in RepairResult::fallback, saying why.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "repair/reformulation.h"
#include "repair/repair_strategy.h"
#include "repair/stable_compilation.h"

namespace alplan::repair {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", x);
  return buffer;
}

// What a new plan does to the old plan's remaining steps, over multisets:
// kept + removed = |old|, kept + added = |new|, removed + added = D.
struct Changes {
  std::size_t kept = 0, removed = 0, added = 0;
};

Changes changes_between(std::vector<std::string> before, std::vector<std::string> after) {
  std::sort(before.begin(), before.end());
  std::sort(after.begin(), after.end());
  std::vector<std::string> common;
  std::set_intersection(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(common));
  return {common.size(), before.size() - common.size(), after.size() - common.size()};
}

pddl::NumericExpression expression(pddl::NumericExpression::Kind kind, std::vector<pddl::NumericExpression> operands) {
  pddl::NumericExpression e;
  e.kind = kind;
  e.operands = std::move(operands);
  return e;
}

// minimize (+ M (* penalty (distance))): M is the problem's metric, negated
// when it is maximised, or the makespan when there is none (a plan's length
// in time is what IPC temporal domains are judged by).
pddl::Metric weighted_metric(const std::optional<pddl::Metric>& metric, const std::string& distance,
                             double penalty) {
  using Kind = pddl::NumericExpression::Kind;
  pddl::NumericExpression quality;
  if (!metric) {
    quality.kind = Kind::TotalTime;
  } else {
    quality = metric->minimize ? metric->expression : expression(Kind::Negate, {metric->expression});
  }
  pddl::NumericExpression weight;
  weight.value = penalty;
  pddl::NumericExpression counter;
  counter.kind = Kind::Function;
  counter.function.name = distance;
  pddl::Metric weighted;
  weighted.minimize = true;
  weighted.expression = expression(Kind::Add, {quality, expression(Kind::Multiply, {weight, counter})});
  return weighted;
}

class AdaptStrategy : public RepairStrategy {
 public:
  explicit AdaptStrategy(StrategyOptions options) : options_(std::move(options)) {}
  std::string name() const override { return "adapt"; }

  RepairResult repair(const RepairRequest& request) override {
    const Clock::time_point began = Clock::now();
    pddl::Problem known = *request.problem;
    RepairRequest seen = request;
    RepairResult result;
    result.integrated = integrate_recognized(seen, known);
    result.problem = reformulate(*request.domain, known, seen.observed, request.in_progress, request.now);
    std::shared_ptr<const GroundTask> task;
    try {
      task = ground_problem(*request.domain, result.problem, request.grounding, &result.reused_grounding);
    } catch (const std::exception& error) {
      result.how = std::string("cannot ground the reformulated problem: ") + error.what();
      return result;
    }
    std::string why;  // set only when the compilation fails: then adapt replans
    try {
      adapt_compiled(seen, task, result, why);
    } catch (const std::exception& error) {
      why = error.what();
    }
    if (!why.empty()) result = fall_back(seen, known, why, result, since(began));
    result.problem.init = known.init;
    result.problem.numeric_init = known.numeric_init;
    result.problem.timed_literals = known.timed_literals;
    result.seconds = since(began);
    return result;
  }

 private:
  // The repairs' planner with its search within the budget: `search` in
  // anytime mode (the fallback's), or the compiled task's search.
  // What is left of adapt_budget after `spent` seconds: a fallback shares
  // the budget with the attempt before it.
  PlannerOptions budgeted(SearchConfiguration search, double spent = 0.0) const {
    PlannerOptions planner = options_.planner;
    planner.search = std::move(search);
    planner.time_limit = std::min(planner.time_limit, std::max(0.0, options_.adapt_budget - spent));
    return planner;
  }

  SearchConfiguration replan_search() const {
    return with_anytime(options_.planner.search, options_.adapt_min_weight, options_.adapt_expansions);
  }

  // The compiled task's search: the repairs' own first search (their
  // anytime search's first, with_anytime's rule) for a plan, then the
  // anytime weights ordered by the metric, guided by landmark cuts
  // (heuristic=lmcut) instead of the relaxed plan. In the compilation the
  // earliest achiever of every (alplan-done-i) is forgo-i, at time 0, so
  // the relaxed plan charges a penalty for every old step still pending
  // whether it will be kept or not, and weighted search on it forgoes old
  // steps early: on the five-step task of adapt_strategy_test.cpp where
  // nothing failed, the weights 5 and 3 on it ended at distance 4 (value
  // 424) where keeping every step is worth 24, and the file's cases that
  // need a removal avoided failed. Landmark cuts count keep-i at its cost
  // of 0. Landmark cuts for the first plan as well spent half the budget
  // on driverlog-time's repairs without finding one. PDDL 3 tasks keep
  // their preferences engine around it.
  SearchConfiguration compiled_search(const SearchConfiguration& planner) const {
    const EngineSpec& e = planner.engine;
    if (e.kind == EngineSpec::Kind::Preferences) {
      SearchConfiguration result = planner;
      result.engine.children.front() = compiled_search(SearchConfiguration{e.children.front()}).engine;
      return result;
    }
    const SearchConfiguration first =
        e.kind == EngineSpec::Kind::Anytime ? SearchConfiguration{e.children.front()} : planner;
    SearchConfiguration search = parse_search_configuration(
        anytime_expression(first.to_string(), options_.adapt_min_weight, options_.adapt_expansions, true));
    search.engine.heuristic.kind = HeuristicSpec::Kind::LmCut;
    search.engine.own_heuristic = true;
    return search;
  }

  // Plans the compilation of result.problem and fills `result` in. No plan
  // in the budget leaves it unrepaired with the planner's reason; a
  // compilation that yields no valid plan leaves it unrepaired with `why`.
  void adapt_compiled(const RepairRequest& request, const std::shared_ptr<const GroundTask>& task,
                      RepairResult& result, std::string& why) const {
    StableCompilation compiled = compile_stability(*request.domain, result.problem,
                                                   remaining_steps(*request.plan, request.now), DistanceCounter::Apart);
    compiled.problem.metric = weighted_metric(result.problem.metric, compiled.distance, options_.adapt_penalty);
    const PlannerOptions planner = budgeted(compiled_search(options_.planner.search));
    const std::shared_ptr<const GroundTask> searched = ground_problem(compiled.domain, compiled.problem, nullptr);
    PlanningStart start = initial_start(*searched);
    start.now = request.now;
    const PlannerResult planned = Planner(searched, planner).plan_from(start);
    result.planner_calls = 1;
    const FoundPlan* best = planned.best();
    if (!best) {
      result.how = no_plan_reason(planned.status, planned.message);
      return;
    }
    std::optional<ExecutingPlan> plan =
        bind_validated(task, map_back(compiled, best->plan).plan, request.now, planner.epsilon, why);
    if (!plan) {
      why = "the compiled plan maps to an invalid plan (" + why + ")";
      return;
    }
    const Changes c = changes_between(step_names_from(*request.plan, request.now), step_names_from(*plan, request.now));
    result.how = describe(c, result.problem.metric.has_value()) + describe_remedy(*plan, request.now);
    result.plan = std::move(plan);
    result.repaired = true;
  }

  // Counted on the plans themselves, not on the compiled plan's keep and
  // forgo steps: an anytime plan may forgo an old step and add the same
  // action, which changes nothing.
  std::string describe(const Changes& c, bool metric) const {
    return "adapted the old plan: " + std::to_string(c.kept) + " of its " + std::to_string(c.kept + c.removed) +
           " remaining steps are kept, " + std::to_string(c.removed) + " removed, " + std::to_string(c.added) +
           " added (distance " + std::to_string(c.removed + c.added) + ", each change weighed " +
           number(options_.adapt_penalty) + " against " +
           (metric ? "the metric" : "the makespan, the task having no metric") + "); ";
  }

  RepairResult fall_back(const RepairRequest& request, const pddl::Problem& known, const std::string& why,
                         const RepairResult& tried, double spent) const {
    RepairResult result = replan_from(request, *request.domain, known, budgeted(replan_search(), spent));
    result.planner_calls += tried.planner_calls;
    result.integrated = tried.integrated;
    result.fallback = "replan";
    const std::string what = result.repaired ? describe_remedy(*result.plan, request.now) : result.how;
    result.how = "adapt could not plan on the stability compilation (" + why +
                 "), so it fell back to replan (anytime search in what was left of its budget): " + what;
    return result;
  }

  StrategyOptions options_;
};

}  // namespace

std::unique_ptr<RepairStrategy> make_adapt_strategy(const StrategyOptions& options) {
  return std::make_unique<AdaptStrategy>(options);
}

}  // namespace alplan::repair
