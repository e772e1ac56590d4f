// switch: keep k diverse plans for the goal (planner/diverse_plans.h: the
// iterate-and-forbid scheme of Katz & Sohrabi, AAAI 2020, with actions
// forbidden instead of whole plans, and Nguyen et al.'s action-set
// distance, AIJ 2012) and, on a failure, switch to the best alternative
// still executable from the observed state; replan only when none is.
//
// Where the alternatives come from. The strategy interface has no hook for
// the moment the mission's plan is made, so the strategy computes them the
// first time it sees a problem's goal, from the problem's initial state
// (the mission's, as the request's problem carries it: the world, not the
// problem, says what holds now), and caches them in the instance, keyed by
// the problem (objects, initial state, goal). The first repair of each goal pays for the
// k searches in its latency and planner calls; later ones pay only for
// validation. A goal the mission changes to (an emotion change) gets its
// own set, still planned from the initial state: an alternative is only
// ever used through its remainder that validates from the observed state.
//
// Which remainder. An alternative is executable when one of its suffixes
// (steps i..n, by start time) validates from the observed state, actions in
// progress committed as in every strategy (reformulation.h), with the
// suffix moved to start now, or once the actions in progress end, or at its
// own time if that is later. The earlier
// steps are those whose effects the world already holds (the robot has
// walked that part of the route) or no longer needs. Among all executable
// suffixes of all alternatives, the best has the lowest metric (the
// makespan without one), ties broken by the fewest actions changed from
// the failed plan's remainder (plan_distance, the study's stability).
#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pddl_parser/writer.h"
#include "planner/diverse_plans.h"
#include "repair/reformulation.h"
#include "repair/repair_strategy.h"

namespace alplan::repair {
namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

struct Alternatives {
  std::vector<Plan> plans;
  std::string why_none;  // when there are no plans
};

struct Candidate {
  ExecutingPlan plan;
  std::size_t alternative = 0, first_step = 0;
  double score = std::numeric_limits<double>::infinity();
  std::size_t distance = 0;
};

// Steps i.. of a plan, moved so that the first starts at `start`.
Plan suffix_from(const Plan& plan, std::size_t first, double start) {
  Plan out;
  const double shift = start - plan.steps[first].time.value_or(0.0);
  for (std::size_t i = first; i < plan.steps.size(); ++i) {
    PlanStep step = plan.steps[i];
    step.time = step.time.value_or(0.0) + shift;
    out.steps.push_back(std::move(step));
  }
  return out;
}

// When a suffix may start: now; once the actions in progress have ended
// (their ends are timed literals of the reformulated task, and the robot is
// busy until then); and at its own time, if that is later (a window it was
// scheduled for).
std::vector<double> start_times(const RepairRequest& request, const PlanStep& first, double epsilon) {
  std::vector<double> out{request.now};
  double busy = request.now;
  for (const ActionInProgress& a : request.in_progress) busy = std::max(busy, a.expected_end + epsilon);
  if (busy > request.now) out.push_back(busy);
  const double own = first.time.value_or(0.0);
  if (own > busy) out.push_back(own);
  return out;
}

bool better(const Candidate& a, const Candidate& b) {
  if (a.score < b.score - 1e-9) return true;
  if (a.score > b.score + 1e-9) return false;
  return a.distance < b.distance;
}

class SwitchStrategy : public RepairStrategy {
 public:
  explicit SwitchStrategy(StrategyOptions options) : options_(std::move(options)) {}
  std::string name() const override { return "switch"; }

  RepairResult repair(const RepairRequest& request) override {
    const auto began = std::chrono::steady_clock::now();
    int calls = 0;
    const Alternatives& alternatives = alternatives_for(request, calls);
    std::optional<Candidate> best;
    bool reused = false;
    if (!alternatives.plans.empty()) best = best_executable(request, alternatives, reused);
    if (best) {
      RepairResult result;
      result.repaired = true;
      result.problem = *request.problem;
      result.planner_calls = calls;
      result.reused_grounding = reused;
      result.how = "switched to alternative " + std::to_string(best->alternative + 1) + " of " +
                   std::to_string(alternatives.plans.size()) + " diverse plans kept for the goal, from its step " +
                   std::to_string(best->first_step + 1) + (calls ? " (the alternatives were planned now, " +
                   std::to_string(calls) + " planner calls)" : std::string(", without search")) + "; " +
                   describe_remedy(best->plan, request.now);
      result.plan = std::move(best->plan);
      result.seconds = since(began);
      return result;
    }
    RepairResult result = replan_from(request, *request.domain, *request.problem, options_.planner);
    result.planner_calls += calls;
    result.fallback = "replan";
    const std::string why = alternatives.plans.empty()
                                ? "no diverse plans were found for the goal (" + alternatives.why_none + ")"
                                : "none of the " + std::to_string(alternatives.plans.size()) +
                                      " diverse plans kept for the goal is executable from the observed state";
    result.how = why + ", so it replanned: " +
                 (result.repaired ? describe_remedy(*result.plan, request.now) : result.how);
    result.seconds = since(began);
    return result;
  }

 private:
  // The cached set for the request's goal, planned on first sight.
  const Alternatives& alternatives_for(const RepairRequest& request, int& calls) {
    const pddl::Problem& problem = *request.problem;
    // The whole problem, not its name: the study's homes may share names,
    // and a goal the mission changes to is another problem.
    const std::string key = pddl::write_problem(problem);
    const auto cached = cache_.find(key);
    if (cached != cache_.end()) return cached->second;
    Alternatives made;
    try {
      DiversePlanOptions diverse;
      diverse.k = options_.switch_plans;
      diverse.min_distance = options_.switch_min_distance;
      diverse.planner = options_.planner;
      diverse.planner.time_limit = std::min(diverse.planner.time_limit, options_.switch_budget);
      diverse.planner.node_limit = options_.switch_expansions;
      const DiversePlans found = find_diverse_plans(ground_problem(*request.domain, problem, request.grounding), diverse);
      calls = static_cast<int>(found.planner_calls);
      for (const FoundPlan& p : found.plans) made.plans.push_back(p.plan);
      made.why_none = found.message;
    } catch (const std::exception& error) {
      made.why_none = std::string("cannot ground the problem: ") + error.what();
    }
    return cache_.emplace(key, std::move(made)).first->second;
  }

  std::optional<Candidate> best_executable(const RepairRequest& request, const Alternatives& alternatives,
                                           bool& reused) const {
    const pddl::Problem reformulated =
        reformulate(*request.domain, *request.problem, request.observed, request.in_progress, request.now);
    std::shared_ptr<const GroundTask> task;
    try {
      task = ground_problem(*request.domain, reformulated, request.grounding, &reused);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    std::optional<Candidate> best;
    for (std::size_t a = 0; a < alternatives.plans.size(); ++a) {
      const Plan& plan = alternatives.plans[a];
      for (std::size_t first = 0; first < plan.steps.size(); ++first) {
        for (double start : start_times(request, plan.steps[first], options_.planner.epsilon)) {
          std::optional<Candidate> c = executable(task, request, suffix_from(plan, first, start));
          if (!c) continue;
          c->alternative = a;
          c->first_step = first;
          if (!best || better(*c, *best)) best = std::move(c);
        }
      }
    }
    return best;
  }

  // The remainder bound to the reformulated task, when it validates there.
  std::optional<Candidate> executable(const std::shared_ptr<const GroundTask>& task, const RepairRequest& request,
                                      const Plan& remainder) const {
    Candidate c;
    try {
      c.plan = bind_plan(task, remainder, options_.planner.epsilon);
    } catch (const std::invalid_argument&) {
      return std::nullopt;  // a step the observed world cannot ground (an object gone)
    }
    const ValidationResult v = validate_from_now(c.plan, request.now);
    if (!v.valid) return std::nullopt;
    c.score = v.metric.value_or(v.makespan);
    c.distance = plan_distance(*request.plan, c.plan, request.now);
    return c;
  }

  StrategyOptions options_;
  // The diverse plans per problem (its text): this instance's own,
  // filled as it meets goals (one instance serves one study's runs).
  std::map<std::string, Alternatives> cache_;
};

}  // namespace

std::unique_ptr<RepairStrategy> make_switch_strategy(const StrategyOptions& options) {
  return std::make_unique<SwitchStrategy>(options);
}

}  // namespace alplan::repair
