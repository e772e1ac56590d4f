// adapt: plan adaptation in the spirit of LPG-ADAPT (Gerevini & Serina 2000;
// compared with replanning for plan stability by Fox et al., ICAPS 2006):
// reuse the old plan as far as possible. The reformulated task becomes a
// view in which every action the remaining plan does not contain costs a
// penalty (added to total-cost), and anytime search under a small budget
// minimises the metric plus the penalties — so among good plans it prefers
// those closest to the old one. The plan then runs on the unpenalised task.
// A domain without (total-cost) gets one on a copy (with_action_cost).
#include <chrono>
#include <set>

#include "repair/reformulation.h"
#include "repair/repair_strategy.h"
#include "repair/stable_compilation.h"

namespace alplan::repair {
namespace {

std::optional<NumericVarId> total_cost(const GroundTask& task) {
  for (NumericVarId v = 0; v < task.numeric.size(); ++v) {
    const GroundKey& key = task.numeric.key(v);
    if (key.args.empty() && task.lifted->functions[key.head].name == "total-cost") return v;
  }
  return std::nullopt;
}

// The task with a penalty on every action outside `keep`; the metric gains
// total-cost when it did not count it.
std::shared_ptr<const GroundTask> penalised(const GroundTask& task, const std::multiset<std::string>& keep,
                                            NumericVarId cost, double penalty) {
  auto view = std::make_shared<GroundTask>(task);
  GroundExpression amount;
  amount.value = penalty;
  for (GroundAction& a : view->actions.mutate()) {
    if (keep.count(view->action_name(a))) continue;
    (a.durative ? a.end : a.start).numeric.push_back({cost, pddl::AssignOperator::Increase, amount});
  }
  GroundExpression cost_term;
  cost_term.kind = GroundExpression::Kind::Variable;
  cost_term.variable = cost;
  if (!view->metric) {
    GroundExpression time;
    time.kind = GroundExpression::Kind::TotalTime;
    view->metric = GroundMetric{true, time};
  }
  GroundExpression sum;
  sum.kind = GroundExpression::Kind::Add;
  sum.operands = {view->metric->expression, cost_term};
  view->metric->expression = sum;
  return view;
}

class AdaptStrategy : public RepairStrategy {
 public:
  explicit AdaptStrategy(StrategyOptions options) : options_(std::move(options)) {}
  std::string name() const override { return "adapt"; }

  RepairResult repair(const RepairRequest& request) override {
    const auto began = std::chrono::steady_clock::now();
    RepairResult result;
    pddl::Problem known = *request.problem;
    RepairRequest seen = request;
    result.integrated = integrate_recognized(seen, known);
    result.problem = reformulate(*request.domain, known, seen.observed, request.in_progress, request.now);
    std::shared_ptr<const GroundTask> task;
    try {
      task = ground_problem(*request.domain, result.problem, request.grounding, &result.reused_grounding);
    } catch (const std::exception& error) {
      result.how = std::string("cannot ground the reformulated problem: ") + error.what();
      return result;
    }
    std::multiset<std::string> keep;
    for (const ScheduledAction& s : request.plan->steps) {
      if (s.start + 1e-9 >= request.now) keep.insert(s.name);
    }
    // IPC temporal domains have no action costs: the penalties go on a
    // grounding of a copy that declares (total-cost), which every action
    // increases by 0 so that the grounder keeps it as a variable (it keeps
    // only functions some action changes), starting at 0 (a problem may
    // leave it undefined). The plan is bound to `task`.
    std::shared_ptr<const GroundTask> searched = task;
    const bool costs_added = !total_cost(*task);
    if (costs_added) {
      try {
        const pddl::Domain costed = declares_total_cost(*request.domain) ? *request.domain
                                                                          : with_action_cost(*request.domain, 0.0);
        searched = ground_problem(costed, with_zero_cost(result.problem), nullptr);
      } catch (const std::exception& error) {
        result.how = std::string("cannot ground the reformulated problem with action costs: ") + error.what();
        return result;
      }
    }
    const std::optional<NumericVarId> cost = total_cost(*searched);
    PlannerOptions planner = options_.planner;
    planner.search = with_anytime(planner.search, options_.adapt_min_weight, options_.adapt_expansions);
    planner.time_limit = std::min(planner.time_limit, options_.adapt_budget);
    const std::shared_ptr<const GroundTask> view =
        cost ? penalised(*searched, keep, *cost, options_.adapt_penalty) : searched;
    PlanningStart start = initial_start(*view);
    start.now = request.now;
    const PlannerResult planned = Planner(view, planner).plan_from(start);
    result.planner_calls = 1;
    if (const FoundPlan* best = planned.best()) {
      result.plan = bind_plan(task, best->plan, planner.epsilon);
      result.repaired = true;
      std::size_t reused = 0;
      for (const ScheduledAction& s : result.plan->steps) reused += keep.count(s.name) ? 1 : 0;
      result.how = "adapted the old plan: " + std::to_string(reused) + " of its " + std::to_string(keep.size()) +
                   " remaining steps are kept" + (costs_added ? " (changes counted on a total-cost the task lacked)" : "") +
                   "; " + describe_remedy(*result.plan, request.now);
    } else {
      result.how = no_plan_reason(planned.status, planned.message);
    }
    if (!cost) {
      // Without action costs there is nothing to penalise change with: say
      // so, and name what was done instead.
      result.fallback = "replan";
      result.how = "adapt needs a total-cost function to penalise changes to the old plan and even a copy of "
                   "the domain that declares one grounds without it, so it fell back to replan (anytime search): " +
                   result.how;
    }
    result.problem.init = known.init;
    result.problem.numeric_init = known.numeric_init;
    result.problem.timed_literals = known.timed_literals;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    return result;
  }

 private:
  StrategyOptions options_;
};

}  // namespace

std::unique_ptr<RepairStrategy> make_adapt_strategy(const StrategyOptions& options) {
  return std::make_unique<AdaptStrategy>(options);
}

}  // namespace alplan::repair
