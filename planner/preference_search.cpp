#include "planner/preference_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "planner/formula_evaluation.h"
#include "planner/explicit_state.h"
#include "planner/linear_metric.h"
#include "planner/pddl3_compilation.h"
#include "planner/trajectory_monitor.h"
#include "planner/violation_weights.h"

namespace alplan {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The plan without the compilation's witness steps; the text keeps its
// other lines as printed (one per step).
FoundPlan without_witnesses(const FoundPlan& found, const std::set<std::string>& witnesses) {
  FoundPlan out = found;
  out.plan.steps.clear();
  out.text.clear();
  std::istringstream lines(found.text);
  std::string line;
  for (const PlanStep& step : found.plan.steps) {
    std::getline(lines, line);
    if (witnesses.count(step.action)) continue;
    out.plan.steps.push_back(step);
    out.text += line + "\n";
  }
  return out;
}

// What one preference's violations cost the metric: the metric with the
// best plan's counts, against the same with this preference's set to 0
// (the other terms are the same in both and cancel when it is linear).
double saving(const GroundTask& task, std::vector<double> violations, std::uint32_t preference) {
  if (!task.metric) return 0.0;
  EvaluationContext context;
  context.total_time = 0.0;
  context.violations = &violations;
  ExplicitState state;
  for (NumericVarId v = 0; v < task.initial_values.size(); ++v) state.set_value(v, task.initial_values[v]);
  try {
    const double with = evaluate(task.metric->expression, state, context);
    violations[preference] = 0.0;
    const double without = evaluate(task.metric->expression, state, context);
    return minimised(task, with) - minimised(task, without);
  } catch (const EvaluationError&) {
    return 0.0;
  }
}

class Rounds {
 public:
  // `seen`: the monitor of the states before an observed start; null from
  // the task's initial state.
  Rounds(std::shared_ptr<const GroundTask> task, const PlannerOptions& options, const PlanningStart& start,
         std::shared_ptr<const TrajectoryMonitor> seen, const std::function<void(const FoundPlan&)>& on_plan)
      : task_(std::move(task)), options_(options), start_(start), seen_(std::move(seen)), on_plan_(on_plan),
        began_(Clock::now()), validator_(task_->lifted, ValidatorOptions{options.tolerance, false}),
        metric_is_lower_bound_(compiled_metric_is_lower_bound(*task_)) {}

  double remaining() const { return options_.time_limit - since(began_); }
  PlannerResult& result() { return result_; }
  const FoundPlan* best() const { return result_.best(); }

  // Plans the task compiled with `selection` by `search` for at most
  // `seconds`; true when it gave a better plan than the best so far.
  std::pair<bool, PlannerResult> run(const PreferenceSelection& selection, const SearchConfiguration& search,
                                     double seconds) {
    const TrajectorySoFar so_far{seen_.get(), start_.now, seen_ ? &start_.facts : nullptr};
    const CompiledTrajectory compiled = compile_trajectory(*task_, selection, so_far, options_.epsilon);
    PlannerResult inner;
    if (compiled.refused || compiled.broken) {
      inner.status = compiled.broken ? PlannerResult::Status::Unsolvable : PlannerResult::Status::Unsupported;
      inner.message = compiled.broken ? "no plan exists: the hard constraint " + *compiled.broken : *compiled.refused;
      return {false, inner};
    }
    std::set<std::string> witnesses;
    for (std::size_t s = task_->lifted->actions.size(); s < compiled.task->lifted->actions.size(); ++s) {
      witnesses.insert(compiled.task->lifted->actions[s].name);
    }
    PlannerOptions options = options_;
    options.search = search;
    options.time_limit = std::max(0.0, seconds);
    options.validate_ground = true;
    bool improved = false;
    const Clock::time_point round_began = Clock::now();
    const PlanningStart from = seen_ ? compiled_start(*compiled.task) : initial_start(*compiled.task);
    // Each plan the compiled task gives is judged on the task, violations
    // counted: the search hands on, and its anytime phases bound by, the
    // best value under the task's own metric, not the compiled one's.
    options.objective.metric_is_lower_bound = metric_is_lower_bound_;
    options.objective.value = [&](const FoundPlan& found) -> std::optional<double> {
      if (result_.status == PlannerResult::Status::InternalError) return std::nullopt;
      FoundPlan plan = without_witnesses(found, witnesses);
      const Clock::time_point validation_began = Clock::now();
      plan.validation = seen_ ? validate_observed(plan.text)
                              : validator_.validate(read_plan(plan.text, "planner output").plan);
      result_.times.validation += since(validation_began);
      plan.seconds = std::chrono::duration<double>(round_began - began_).count() + found.seconds;
      if (!plan.validation.valid) {
        result_.status = PlannerResult::Status::InternalError;
        result_.message = "the planner produced a plan the validator rejects: " +
                          plan.validation.violation->message() + "\n" + plan.text;
        return std::nullopt;
      }
      const double value = minimised(*task_, plan.validation.value);
      if (!best() || better(plan.validation.value, best()->validation.value)) {
        improved = true;
        if (on_plan_) on_plan_(plan);
        result_.plans.push_back(std::move(plan));
      }
      return std::min(value, minimised(*task_, best()->validation.value));
    };
    inner = TemporalPlanner(compiled.task, options).plan_from(from);
    add_statistics(inner);
    return {improved, inner};
  }

  bool better(double a, double b) const { return minimised(*task_, a) < minimised(*task_, b) - 1e-9; }

 private:
  // The observed start on the compiled task: its ids extend the task's, and
  // the facts it adds that hold at first (a `within` still open) hold.
  PlanningStart compiled_start(const GroundTask& compiled) const {
    PlanningStart from = start_;
    from.history.clear();  // settled by the compilation
    for (FactId f : compiled.initial_facts) {
      if (f >= task_->facts.size()) from.facts.push_back(f);
    }
    std::sort(from.facts.begin(), from.facts.end());
    return from;
  }

  // A plan from the observed state, validated on the task with the
  // trajectory seen so far carried on (its value counts it all). The
  // compiled task kept the task's action ids, but the plan comes as text.
  ValidationResult validate_observed(const std::string& text) {
    if (action_ids_.empty()) {
      for (ActionId a = 0; a < task_->actions.size(); ++a) action_ids_.emplace(task_->action_name(task_->actions[a]), a);
    }
    const Plan printed = read_plan(text, "planner output").plan;
    std::vector<ActionId> actions;
    for (const PlanStep& p : printed.steps) {
      std::string name = "(" + p.action;
      for (const std::string& arg : p.args) name += " " + arg;
      const auto id = action_ids_.find(name + ")");
      if (id == action_ids_.end()) throw std::logic_error("a planned step the task lacks: " + name + ")");
      actions.push_back(id->second);
    }
    return validate_printed_from(*task_, start_, printed, actions, {}, options_.tolerance, seen_);
  }

  void add_statistics(const PlannerResult& inner) {
    result_.statistics += inner.statistics;
    result_.times.setup += inner.times.setup;
    result_.times.search += inner.times.search;
    if (inner.search_memory) memory_.push_back(inner.search_memory);
    result_.search_memory = std::make_shared<std::vector<std::shared_ptr<void>>>(memory_);
  }

  std::shared_ptr<const GroundTask> task_;
  const PlannerOptions& options_;
  const PlanningStart& start_;
  std::shared_ptr<const TrajectoryMonitor> seen_;
  std::unordered_map<std::string, ActionId> action_ids_;  // by printed name, filled when first needed
  const std::function<void(const FoundPlan&)>& on_plan_;
  Clock::time_point began_;
  PlanValidator validator_;
  // The compiled tasks' metric never exceeds the task's (violation_weights.h).
  bool metric_is_lower_bound_;
  PlannerResult result_;
  std::vector<std::shared_ptr<void>> memory_;
};

// The preferences the best plan violates that the compilation can enforce,
// the costliest first.
std::vector<std::uint32_t> candidates(const GroundTask& task, const ValidationResult& best,
                                      const PreferenceSelection& selection) {
  const std::vector<std::string>& names = task.lifted->pddl3.preferences;
  std::vector<double> violations(names.size(), 0.0);
  for (std::uint32_t p = 0; p < names.size(); ++p) {
    const auto it = best.preference_violations.find(names[p]);
    if (it != best.preference_violations.end()) violations[p] = it->second;
  }
  std::vector<std::pair<double, std::uint32_t>> ranked;
  for (std::uint32_t p = 0; p < names.size(); ++p) {
    if (violations[p] <= 0.0 || selection.contains(p) || !enforceable(task, p)) continue;
    const double gain = saving(task, violations, p);
    if (gain > 1e-9) ranked.emplace_back(gain, p);
  }
  std::stable_sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<std::uint32_t> out;
  for (const auto& r : ranked) out.push_back(r.second);
  return out;
}

// `selection` and every enforceable preference the plan violates nowhere.
PreferenceSelection with_met(const GroundTask& task, const ValidationResult& plan, PreferenceSelection selection) {
  const std::vector<std::string>& names = task.lifted->pddl3.preferences;
  for (std::uint32_t p = 0; p < names.size(); ++p) {
    const auto it = plan.preference_violations.find(names[p]);
    const bool violated = it != plan.preference_violations.end() && it->second > 0.0;
    if (!violated && enforceable(task, p)) selection.enforced[p] = true;
  }
  return selection;
}

}  // namespace

PreferenceSearch::PreferenceSearch(std::shared_ptr<const GroundTask> task, PlannerOptions options)
    : task_(std::move(task)), options_(std::move(options)) {}

PlannerResult PreferenceSearch::plan(const std::function<void(const FoundPlan&)>& on_plan) {
  return plan_from(initial_start(*task_), on_plan);
}

PlannerResult PreferenceSearch::plan_from(const PlanningStart& start,
                                          const std::function<void(const FoundPlan&)>& on_plan) {
  std::shared_ptr<const TrajectoryMonitor> seen;
  if (!is_initial_start(*task_, start)) {
    PlannerResult refused;
    refused.status = PlannerResult::Status::Unsupported;
    if (!start.running.empty()) {
      refused.message = "PDDL 3 from an observed state with actions still running is not supported: commit their "
                        "ends as timed literals";
      return refused;
    }
    auto monitor = std::make_shared<TrajectoryMonitor>(*task_, ValidatorOptions{}.numeric_slack);
    try {
      for (const ObservedState& h : start.history) monitor->observe(ExplicitState::of(h.facts, h.values), h.time);
    } catch (const EvaluationError& error) {
      refused.message = std::string("the states observed before cannot be judged: ") + error.what();
      return refused;
    }
    seen = std::move(monitor);
  }
  const PreferencePlan spec = preference_plan(options_.search);
  Rounds rounds(task_, options_, start, seen, on_plan);
  PreferenceSelection selection;
  selection.enforced.assign(task_->lifted->pddl3.preferences.size(), false);
  auto [found, first] = rounds.run(selection, spec.first, rounds.remaining());
  PlannerResult& result = rounds.result();
  if (result.status == PlannerResult::Status::InternalError) return std::move(result);
  if (!found) {
    // Round 0 is the task with its hard constraints (pddl3_compilation.h):
    // its verdict is the task's, and where the compilation is not exact its
    // exhaustion says so (GroundTrajectory::approximations).
    first.statistics = result.statistics;
    first.times = result.times;
    first.search_memory = result.search_memory;
    return first;
  }
  if (spec.rounds) {
    std::vector<std::uint32_t> queue = candidates(*task_, result.best()->validation, selection);
    std::set<std::uint32_t> tried;
    while (!queue.empty() && rounds.remaining() > 0.0) {
      const std::uint32_t p = queue.front();
      tried.insert(p);
      PreferenceSelection next = selection;
      next.enforced[p] = true;
      // A share of the time left, the anytime phases on the best selection
      // counted as one more share.
      const double share = rounds.remaining() / static_cast<double>(queue.size() + 1);
      // First with every preference the best plan meets held too, so that
      // meeting p cannot cost what the best plan has; then p alone.
      const PreferenceSelection keeping = with_met(*task_, result.best()->validation, next);
      const bool more = keeping.enforced != next.enforced;
      if (more && rounds.run(keeping, spec.first, share / 2).first) {
        selection = keeping;
      } else if (result.status != PlannerResult::Status::InternalError &&
                 rounds.run(next, spec.first, more ? share / 2 : share).first) {
        selection = next;
      }
      if (result.status == PlannerResult::Status::InternalError) return std::move(result);
      queue.clear();
      for (std::uint32_t c : candidates(*task_, result.best()->validation, selection)) {
        if (!tried.count(c)) queue.push_back(c);
      }
    }
  }
  if (spec.improve && rounds.remaining() > 0.0) rounds.run(selection, *spec.improve, rounds.remaining());
  if (result.status != PlannerResult::Status::InternalError) result.status = PlannerResult::Status::Solved;
  return std::move(result);
}

}  // namespace alplan
