#include "planner/temporal_planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "planner/blind_heuristic.h"
#include "planner/lmcut_heuristic.h"
#include "planner/formula_evaluation.h"
#include "planner/happening_executor.h"
#include "planner/linear_metric.h"
#include "planner/action_elimination.h"
#include "planner/plan_deordering.h"
#include "planner/search_engine.h"
#include "planner/search_pipeline.h"
#include "planner/task_index.h"

namespace alplan {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string plan_text(const Plan& plan) {
  std::string out;
  for (const PlanStep& step : plan.steps) {
    if (step.time) out += format_plan_time(*step.time) + ": ";
    out += "(" + step.action;
    for (const std::string& a : step.args) out += " " + a;
    out += ")";
    if (step.duration) out += " [" + format_plan_time(*step.duration) + "]";
    out += "\n";
  }
  return out;
}

// Timed literals that add and delete one fact at one time: VAL judges their
// happening a mutex, and every plan runs through it (the goal is checked
// after the last timed literal), so no plan is valid. Literals within a
// tenth of epsilon form one happening, as in the validator.
std::optional<std::string> clashing_timed_literals(const GroundTask& task, std::uint32_t first, double epsilon) {
  const std::vector<GroundTimedLiteral>& tils = task.timed_literals;
  for (std::size_t g = first; g < tils.size();) {
    std::size_t end = g;
    while (end < tils.size() && tils[end].time - tils[g].time <= epsilon / 10.0) ++end;
    for (std::size_t i = g; i < end; ++i) {
      for (std::size_t j = g; j < end; ++j) {
        if (tils[i].fact == tils[j].fact && tils[i].positive && !tils[j].positive) {
          return "timed initial literals add and delete " + task.fact_name(tils[i].fact) + " at time " +
                 format_plan_time(tils[i].time) + ", a mutex (VAL) in every plan";
        }
      }
    }
    g = end;
  }
  return std::nullopt;
}

std::optional<std::string> broken_always(const GroundTask& task, const PlanningStart& start) {
  if (task.pddl3.constraints.empty()) return std::nullopt;
  const ExplicitState state = ExplicitState::of(start.facts, start.values);
  for (const GroundConstraint& g : task.pddl3.constraints) {
    if (g.op != ModalOperator::Always || g.preference) continue;
    try {
      if (!holds(g.requirement, state, EvaluationContext{}, 0.0)) return g.text;
    } catch (const EvaluationError&) {
      return g.text;
    }
  }
  return std::nullopt;
}

// Validation of a plan made from an observed state, with the running
// actions' ends where the schedule put them.
ValidationResult validate_from(const GroundTask& task, const PlanningStart& start, const Solution& solution,
                               const std::vector<ActionId>& actions, const std::string& text, double epsilon) {
  std::vector<std::pair<ActionId, double>> running_ends;
  for (std::size_t e = 0; e < solution.steps.size(); ++e) {
    const StepRecord& r = solution.steps[e];
    if (r.snap.kind == SnapKind::End && r.start_step == kNoId) running_ends.emplace_back(r.snap.index, solution.times[e]);
  }
  return validate_printed_from(task, start, read_plan(text, "planner output").plan, actions, running_ends, epsilon);
}

}  // namespace

ValidationResult validate_printed_from(const GroundTask& task, const PlanningStart& start, const Plan& printed,
                                       const std::vector<ActionId>& actions,
                                       const std::vector<std::pair<ActionId, double>>& running_ends, double epsilon,
                                       std::shared_ptr<const TrajectoryMonitor> trajectory) {
  std::vector<ScheduledStep> steps;
  for (std::size_t i = 0; i < printed.steps.size(); ++i) {
    const PlanStep& p = printed.steps[i];
    ScheduledStep s;
    s.action = actions[i];
    s.step = i;
    s.line = p.line;
    s.start = p.time.value_or(start.now);
    s.duration = p.duration.value_or(0.0);
    s.name = task.action_name(task.actions[s.action]);
    steps.push_back(s);
  }
  for (const auto& [action, end] : running_ends) {
    ScheduledStep s;
    s.action = action;
    s.step = steps.size();
    s.started_before = true;
    s.start = start.now;
    s.duration = end - start.now;
    s.name = task.action_name(task.actions[s.action]);
    steps.push_back(s);
  }
  ExecutionStart from;
  from.state = ExplicitState::of(start.facts, start.values);
  from.first_timed_literal = start.next_timed_literal;
  from.now = start.now;
  from.trajectory = std::move(trajectory);
  HappeningExecutor executor(task, ValidatorOptions{epsilon, false});
  return executor.run(steps, printed.steps.size(), from);
}

bool is_initial_start(const GroundTask& task, const PlanningStart& start) {
  return start.now == 0.0 && start.running.empty() && start.history.empty() && start.next_timed_literal == 0 &&
         start.facts == task.initial_facts && start.values == task.initial_values;
}

PlanningStart initial_start(const GroundTask& task) {
  PlanningStart start;
  start.facts = task.initial_facts;
  start.values = task.initial_values;
  return start;
}

Plan to_plan(const GroundTask& task, const Solution& solution, std::vector<ActionId>* actions) {
  Plan plan;
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t s = 0; s < solution.steps.size(); ++s) {
    const StepRecord& step = solution.steps[s];
    if (step.snap.kind == SnapKind::Instant || step.snap.kind == SnapKind::Start) order.emplace_back(solution.times[s], s);
  }
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [time, s] : order) {
    const GroundAction& action = task.actions[solution.steps[s].snap.index];
    PlanStep step;
    step.time = time;
    step.action = task.lifted->actions[action.schema].name;
    for (ObjectId o : action.args) step.args.push_back(task.lifted->objects[o]);
    if (action.durative) {
      for (std::size_t e = s + 1; e < solution.steps.size(); ++e) {
        if (solution.steps[e].snap.kind == SnapKind::End && solution.steps[e].start_step == s) {
          step.duration = solution.times[e] - time;
          break;
        }
      }
    }
    plan.steps.push_back(std::move(step));
    if (actions) actions->push_back(solution.steps[s].snap.index);
  }
  return plan;
}

namespace {

std::vector<ActionId> running_actions(const PlanningStart& start) {
  std::vector<ActionId> ids;
  for (const RunningAction& r : start.running) ids.push_back(r.action);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

// Whether the workspace's relevance serves this task: the same ground
// actions and goal, and the running actions among those it kept.
bool relevance_fits(const PlannerWorkspace::Relevance& r, const GroundTask& task, const std::vector<ActionId>& keep) {
  return task.actions.shares_with(r.source) && task.goal.positive == r.goal_positive &&
         task.goal.negative == r.goal_negative && task.goal.numeric.empty() && task.goal.complex.empty() &&
         std::includes(r.kept.begin(), r.kept.end(), keep.begin(), keep.end());
}

// The task's relevant view, through the workspace when it has one.
RelevantView relevance_of(const std::shared_ptr<const GroundTask>& task, const std::vector<ActionId>& keep,
                          PlannerWorkspace* workspace) {
  if (workspace && workspace->relevance && relevance_fits(*workspace->relevance, *task, keep)) {
    return relevant_view_like(task, workspace->relevance->view);
  }
  RelevantView view = relevant_view(task, keep);
  if (workspace) {
    workspace->relevance = std::make_shared<const PlannerWorkspace::Relevance>(
        PlannerWorkspace::Relevance{task->actions, task->goal.positive, task->goal.negative, keep, view});
  }
  return view;
}

}  // namespace

PlannerWorkspace prepare_workspace(std::shared_ptr<const GroundTask> task, bool prune_irrelevant) {
  PlannerWorkspace workspace;
  if (prune_irrelevant) task = relevance_of(task, {}, &workspace).task;
  workspace.index = std::make_shared<const TaskIndex>(std::move(task));
  workspace.graph = TemporalRpg::graph_for(*workspace.index);
  return workspace;
}

TemporalPlanner::TemporalPlanner(std::shared_ptr<const GroundTask> task, PlannerOptions options,
                 std::shared_ptr<PlannerWorkspace> workspace)
    : task_(std::move(task)), options_(std::move(options)), workspace_(std::move(workspace)) {}

PlannerResult TemporalPlanner::plan(const std::function<void(const FoundPlan&)>& on_plan) {
  return plan_from(initial_start(*task_), on_plan);
}

PlannerResult TemporalPlanner::plan_from(const PlanningStart& start,
                                         const std::function<void(const FoundPlan&)>& on_plan) {
  return options_.prune_irrelevant ? plan_relevant(start, on_plan) : search_from(start, on_plan);
}

PlannerResult TemporalPlanner::plan_relevant(const PlanningStart& start,
                                     const std::function<void(const FoundPlan&)>& on_plan) {
  const Clock::time_point began = Clock::now();
  const RelevantView view = relevance_of(task_, running_actions(start), workspace_.get());
  if (view.pruned == 0) return search_from(start, on_plan);
  PlanningStart mapped = start;
  for (RunningAction& r : mapped.running) r.action = view.new_id[r.action];
  PlannerOptions options = options_;
  options.prune_irrelevant = false;
  const double analysis = since(began);
  options.time_limit = std::max(0.0, options_.time_limit - analysis);
  // The budget's reserve still ends where the caller's would have.
  if (options.reserve_planning_time) mapped.now += analysis;
  PlannerResult result = TemporalPlanner(view.task, options, workspace_).search_from(mapped, on_plan);
  result.times.setup += analysis;
  return result;
}

namespace {

// The heuristics a configuration asks for, one per specification, built on
// one shared relaxed graph.
class HeuristicPool {
 public:
  HeuristicPool(const TaskIndex& index, std::shared_ptr<const LinearMetric> metric,
                std::shared_ptr<const TemporalRpg::Graph> graph)
      : index_(index), metric_(std::move(metric)), graph_(std::move(graph)) {}

  Heuristic& get(const HeuristicSpec& spec, bool metric_order) {
    const bool with_metric = metric_order && metric_;
    for (Entry& e : entries_) {
      if (e.spec == spec && e.metric == with_metric) return *e.heuristic;
    }
    Entry e{spec, with_metric, nullptr};
    if (spec.kind == HeuristicSpec::Kind::Blind) {
      e.heuristic = std::make_unique<BlindHeuristic>(index_);
    } else if (spec.kind == HeuristicSpec::Kind::LmCut) {
      e.heuristic = std::make_unique<LmCutHeuristic>(index_, with_metric ? metric_ : nullptr);
    } else {
      TemporalRpgOptions options;
      options.helpful_actions = spec.helpful;
      options.resource_balance = spec.balance;
      options.count_repetitions = spec.repetitions;
      if (with_metric) options.metric = metric_;
      auto rpg = std::make_unique<TemporalRpg>(index_, options, graph_);
      graph_ = rpg->graph();  // the one given when it fits this task, else a new one
      built_ = true;
      e.heuristic = std::move(rpg);
    }
    entries_.push_back(std::move(e));
    return *entries_.back().heuristic;
  }
  // The relaxed graph, built by the first relaxed-graph heuristic asked for.
  const std::shared_ptr<const TemporalRpg::Graph>& graph() {
    if (!built_) get(HeuristicSpec{}, false);
    return graph_;
  }

 private:
  struct Entry {
    HeuristicSpec spec;
    bool metric = false;
    std::unique_ptr<Heuristic> heuristic;
  };
  const TaskIndex& index_;
  std::shared_ptr<const LinearMetric> metric_;
  std::shared_ptr<const TemporalRpg::Graph> graph_;
  bool built_ = false;  // a relaxed-graph heuristic exists, and graph_ is its
  std::vector<Entry> entries_;
};

bool uses_goal_orders(const EngineSpec& e) {
  return e.goal_orders || std::any_of(e.children.begin(), e.children.end(), uses_goal_orders);
}

SearchStart search_start_of(const GroundTask& task, const PlanningStart& start, const PlannerOptions& options) {
  SearchStart search_start;
  search_start.state = SearchState(task.facts.size(), start.values);
  for (FactId f : start.facts) search_start.state.set_fact(f, true);
  search_start.state.set_next_timed_literal(start.next_timed_literal);
  search_start.release = start.now;
  if (options.reserve_planning_time && std::isfinite(options.time_limit)) search_start.release += options.time_limit;
  for (const RunningAction& r : start.running) search_start.state.start(r);
  derive(task, search_start.state);
  return search_start;
}

// Turns a solution into the plan to print: validated as printed (from the
// task's start by the plan validator, from an observed state by
// validate_from), and lifted to the order its causal links need and
// scheduled again (plan_deordering.h), which is kept when it is valid and
// better, or as good and shorter. A plan we print is always one the
// validator accepted.
class PlanChecker {
 public:
  PlanChecker(std::shared_ptr<const GroundTask> task, const PlanningStart& start, const TaskIndex& index,
              const SearchStart& search_start, const PlannerOptions& options)
      : task_(std::move(task)), start_(start), index_(index), search_start_(search_start), options_(options),
        from_initial_(is_initial_start(*task_, start) && !options.validate_ground) {
    // The plan validator grounds the task again for itself: only from the start.
    if (from_initial_) validator_.emplace(task_->lifted, ValidatorOptions{options.tolerance, false});
  }

  FoundPlan check(const Solution& solution, const std::string& engine, const SearchDeadline& deadline) {
    FoundPlan found = validated(solution, engine);
    if (!found.validation.valid || !options_.deorder) return found;
    const DeorderingInput input{index_, search_start_.state, search_start_.release, options_.epsilon};
    Solution kept = solution;
    if (std::optional<Solution> lifted = deorder(input, solution)) {
      FoundPlan candidate = validated(*lifted, engine + ", deordered");
      if (improves(found, candidate, false)) {
        found = std::move(candidate);
        kept = std::move(*lifted);
      }
    }
    // Only from the task's start, where the exact validator can judge: VAL
    // compares numbers with a slack, so `(> lit 0)` holds at 0 and a plan
    // without the steps that raise `lit` passes it (match-cellar's mends
    // without their matches); the search never relies on the slack, and
    // neither may a removal.
    if (!options_.eliminate_actions || !from_initial_) return found;
    const std::string eliminated = found.engine + ", actions eliminated";
    auto accept = [&](const Solution& fewer) {
      FoundPlan candidate = validated(fewer, eliminated);
      if (!improves(found, candidate, true)) return false;
      if (!validator_->validate_exactly(read_plan(candidate.text, "planner output").plan).valid) return false;
      found = std::move(candidate);
      return true;
    };
    eliminate_actions(input, kept, accept, {elimination_deadline(deadline)});
    return found;
  }

 private:
  // Elimination holds the plan back from the caller (and an anytime search
  // from its next phase): at most a tenth of the time left, or a second.
  static SearchDeadline elimination_deadline(const SearchDeadline& deadline) {
    if (!deadline) return deadline;
    const auto now = std::chrono::steady_clock::now();
    const auto share = std::max<std::chrono::steady_clock::duration>(std::chrono::seconds(1), (*deadline - now) / 10);
    return std::min(*deadline, now + share);
  }

  // Whether a valid candidate replaces the plan: better under the metric's
  // own direction (a maximised one is larger), or at an equal value shorter
  // (a task without a metric counts steps); `fewer_actions`: at an equal
  // value and makespan too, since it has fewer actions.
  bool improves(const FoundPlan& plan, const FoundPlan& candidate, bool fewer_actions) const {
    if (!candidate.validation.valid) return false;
    const double shorter = plan.validation.makespan - candidate.validation.makespan;
    // Without a metric the value counts steps, which a removal always
    // lowers: an eliminated plan must not be longer either.
    if (fewer_actions && !task_->metric && shorter < -1e-9) return false;
    const double gain = minimised(*task_, plan.validation.value) - minimised(*task_, candidate.validation.value);
    if (gain > 1e-9) return true;
    if (gain < -1e-9) return false;
    return shorter > 1e-9 || (fewer_actions && shorter >= -1e-9);
  }

  FoundPlan validated(const Solution& solution, const std::string& engine) {
    FoundPlan found;
    std::vector<ActionId> actions;
    found.plan = to_plan(*task_, solution, &actions);
    found.text = plan_text(found.plan);
    found.engine = engine;
    found.validation = from_initial_ ? validator_->validate(read_plan(found.text, "planner output").plan)
                                     : validate_from(*task_, start_, solution, actions, found.text, options_.tolerance);
    return found;
  }

  std::shared_ptr<const GroundTask> task_;
  const PlanningStart& start_;
  const TaskIndex& index_;
  const SearchStart& search_start_;
  const PlannerOptions& options_;
  bool from_initial_;
  std::optional<PlanValidator> validator_;
};

}  // namespace

// What the task refuses before any search: an unsupported construct, a goal
// grounded away, timed literals that clash.
std::optional<PlannerResult> TemporalPlanner::refused(const TaskIndex& index, const PlanningStart& start) const {
  PlannerResult result;
  if (index.unsupported()) {
    result.status = PlannerResult::Status::Unsupported;
    result.message = *index.unsupported();
    return result;
  }
  if (task_->goal.never) {
    result.status = PlannerResult::Status::Unsolvable;
    result.message = "no plan exists: the goal can never hold (" + *task_->goal.never + ")";
    return result;
  }
  if (const auto clash = clashing_timed_literals(*task_, start.next_timed_literal, options_.tolerance)) {
    result.status = PlannerResult::Status::Unsolvable;
    result.message = "no plan exists: " + *clash;
    return result;
  }
  // The search checks `always` in the states it makes; VAL observes the first too.
  if (const auto broken = broken_always(*task_, start)) {
    result.status = PlannerResult::Status::Unsolvable;
    result.message = "no plan exists: " + *broken + " is false where the plan would start";
    return result;
  }
  return std::nullopt;
}

// The gap VAL needs to see two happenings, with its tolerance t: more than
// t/10 (points within t/10 of a happening's first join it). 1e-7 over it,
// so that the printed times (plan.h) keep the happenings apart.
double closest_gap(double tolerance) { return tolerance / 10.0 + 1e-7; }

// Whether a timed literal opens a fact for less than `width` before one
// takes it away (or one takes away an initial fact that soon): a snap that
// reads it fits there only with gaps under epsilon on both sides.
bool has_narrow_windows(const GroundTask& task, double width) {
  std::vector<double> opened(task.facts.size(), -1.0);
  for (FactId f : task.initial_facts) opened[f] = 0.0;
  for (const GroundTimedLiteral& til : task.timed_literals) {  // in order of time
    if (til.positive) {
      if (opened[til.fact] < 0.0) opened[til.fact] = til.time;
    } else {
      if (opened[til.fact] >= 0.0 && til.time - opened[til.fact] < width) return true;
      opened[til.fact] = -1.0;
    }
  }
  return false;
}

PlannerResult TemporalPlanner::search_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan) {
  const Clock::time_point began = Clock::now();
  const bool fallback = options_.close_gap_fallback && options_.epsilon > closest_gap(options_.tolerance);
  // Windows too narrow for epsilon gaps: the search at epsilon may never
  // end (its space need not be finite), so it gets a third of the time and
  // the closer search the rest.
  const bool narrow = fallback && std::isfinite(options_.time_limit) &&
                      has_narrow_windows(*task_, 3.0 * options_.epsilon);
  bool by_search = false;
  PlannerResult result;
  if (narrow) {
    PlannerOptions first = options_;
    first.time_limit = options_.time_limit / 3.0;
    result = TemporalPlanner(task_, first, workspace_).search_once(start, on_plan, by_search);
  } else {
    result = search_once(start, on_plan, by_search);
  }
  const bool retry = (result.status == PlannerResult::Status::Unsolvable && by_search) ||
                     result.status == PlannerResult::Status::Exhausted ||
                     (narrow && result.status == PlannerResult::Status::LimitReached);
  if (!retry || !fallback) return result;
  return search_closer(start, on_plan, std::move(result), since(began));
}

PlannerResult TemporalPlanner::search_closer(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan,
                                     PlannerResult first, double elapsed) {
  PlannerOptions closer = options_;
  closer.epsilon = closest_gap(options_.tolerance);
  closer.search = alias("complete");
  closer.time_limit = std::max(0.0, options_.time_limit - elapsed);
  closer.close_gap_fallback = false;
  bool by_search = false;
  PlannerResult second = TemporalPlanner(task_, closer, workspace_).search_once(start, on_plan, by_search);
  second.statistics.expanded += first.statistics.expanded;
  second.statistics.evaluated += first.statistics.evaluated;
  second.times.setup += first.times.setup;
  second.times.search += first.times.search;
  second.times.validation += first.times.validation;
  const std::string gap = format_plan_time(closer.epsilon);
  const std::string at = "with dependent happenings " + format_plan_time(options_.epsilon) + " apart";
  // The first search settled the epsilon plans only where it proved that
  // none exists; one cut short by its share of the time (narrow windows),
  // or exhausted without a proof, did not.
  const bool first_exhausted = first.status == PlannerResult::Status::Unsolvable;
  std::string first_verdict = "no plan " + at;
  if (first.status == PlannerResult::Status::LimitReached) {
    first_verdict = "no plan was found " + at + " in the first " +
                    format_plan_time(first.times.setup + first.times.search) + " s (not a proof that none exists)";
  } else if (!first_exhausted) {
    first_verdict = "no plan was found " + at + " (" + first.message + ")";
  }
  switch (second.status) {
    case PlannerResult::Status::Solved:
      second.message = first_verdict + "; this plan's are only " + gap +
                       " apart (VAL separates happenings more than " + format_plan_time(options_.tolerance / 10.0) +
                       " apart)";
      return second;
    case PlannerResult::Status::Unsolvable:
      if (by_search) {
        // Every plan with gaps of at least `gap` was searched, the epsilon
        // ones among them: a proof whether or not the first search ended.
        second.message = "no plan exists: the search space is exhausted with dependent happenings " + gap +
                         " apart, the closest VAL (-t " + format_plan_time(options_.tolerance) + ") tells apart" +
                         (first_exhausted ? ", and " + at : "");
      }
      return second;
    default:
      // The first search's verdict stands, and says what it does not prove.
      first.statistics = second.statistics;
      first.times = second.times;
      if (first.status == PlannerResult::Status::Unsolvable) {
        first.status = PlannerResult::Status::Exhausted;
        first.message = "the search space is exhausted " + at + "; this is not a proof: plans whose happenings are "
                        "closer (VAL separates them when more than " + format_plan_time(options_.tolerance / 10.0) +
                        " apart) were not all searched";
      }
      return first;
  }
}

PlannerResult TemporalPlanner::search_once(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan,
                                   bool& by_search) {
  const Clock::time_point began = Clock::now();
  // The limit counts from here, setup included: a caller's budget is wall time.
  PipelineLimits limits{{}, options_.time_limit, options_.node_limit, options_.address_space_limit, options_.epsilon};
  if (std::isfinite(options_.time_limit)) {
    limits.deadline = began + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options_.time_limit));
  }
  const std::shared_ptr<const TaskIndex> shared_index =
      workspace_ && workspace_->index ? std::make_shared<const TaskIndex>(task_, *workspace_->index)
                                      : std::make_shared<const TaskIndex>(task_);
  const TaskIndex& index = *shared_index;
  if (std::optional<PlannerResult> refusal = refused(index, start)) return std::move(*refusal);
  const SearchStart search_start = search_start_of(*task_, start, options_);
  std::shared_ptr<const LinearMetric> metric;
  if (std::optional<LinearMetric> linear = linear_metric(*task_)) metric = std::make_shared<const LinearMetric>(std::move(*linear));
  HeuristicPool heuristics(index, metric, workspace_ ? workspace_->graph : nullptr);
  if (workspace_) {
    workspace_->index = shared_index;
    workspace_->graph = heuristics.graph();
  }
  // The goal orders cost an h^2 fixpoint, paid only where an engine prunes
  // with them; from a state with actions running they are not computed (the
  // compressed task has no running actions to start from).
  std::shared_ptr<const GoalOrders> orders;
  if (uses_goal_orders(options_.search.engine) && start.running.empty()) {
    GoalOrderOptions order_options;
    order_options.mutexes.deadline = limits.deadline;
    orders = std::make_shared<const GoalOrders>(*task_, start.facts, order_options);
  }
  PlanChecker checker(task_, start, index, search_start, options_);
  PlannerResult result;
  result.times.setup = since(began);

  const Clock::time_point search_began = Clock::now();
  const PlannerOptions::Objective& objective = options_.objective;
  double best_objective = std::numeric_limits<double>::infinity();
  auto on_solution = [&](const Solution& solution, const std::string& engine) -> std::optional<SolutionValue> {
    const Clock::time_point validation_began = Clock::now();
    FoundPlan found = checker.check(solution, engine, limits.deadline);
    // When the plan as printed existed: deordering and elimination count.
    found.seconds = std::chrono::duration<double>(Clock::now() - search_began).count();
    result.times.validation += since(validation_began);
    if (!found.validation.valid) {
      result.status = PlannerResult::Status::InternalError;
      result.message = "the planner produced a plan the validator rejects: " + found.validation.violation->message() +
                       "\n" + found.text;
      return std::nullopt;
    }
    const double printed = found.validation.value;
    double value = minimised(*task_, printed);  // smaller is better
    if (objective.value) {
      const std::optional<double> measured = objective.value(found);
      if (!measured) return std::nullopt;
      value = *measured;
    }
    if (result.plans.empty() || value < best_objective - 1e-9) {
      best_objective = value;
      if (on_plan) on_plan(found);
      result.plans.push_back(std::move(found));
    }
    if (!objective.value) return SolutionValue{result.plans.back().validation.value, false};
    // Without a lower bound, a bound would prune plans that are better.
    return SolutionValue{objective.metric_is_lower_bound ? best_objective : std::numeric_limits<double>::infinity(),
                         true, printed};
  };
  const PipelineContext context{index, search_start, metric, orders,
                                [&](const HeuristicSpec& spec, bool metric_order) -> Heuristic& {
                                  return heuristics.get(spec, metric_order);
                                },
                                limits};
  const PipelineOutcome outcome = run_pipeline(options_.search, context, on_solution);
  result.statistics = outcome.statistics;
  result.search_memory = outcome.memory;
  result.times.search = since(search_began) - result.times.validation;
  finish(result, outcome);
  by_search = outcome.proof_by_search;
  return result;
}

// The status and message of a run that returned no error.
void TemporalPlanner::finish(PlannerResult& result, const PipelineOutcome& outcome) const {
  if (result.status == PlannerResult::Status::InternalError) return;
  if (!result.plans.empty()) {
    result.status = PlannerResult::Status::Solved;
  } else if (!outcome.proof.empty()) {
    result.status = PlannerResult::Status::Unsolvable;
    result.message = "no plan exists: " + outcome.proof;
  } else if (!outcome.stopped_at_limit) {
    result.status = PlannerResult::Status::Exhausted;
    result.message = "the search space is exhausted without a plan; this is not a proof: " + outcome.not_proven;
  } else {
    result.status = PlannerResult::Status::LimitReached;
    switch (outcome.limit) {
      case StoppingLimit::Time:
        result.limit = "time";
        result.message = "the time limit was reached before a plan was found (" +
                         format_seconds(options_.time_limit) + " s for the search)";
        break;
      case StoppingLimit::Nodes:
        result.limit = "nodes";
        result.message = "the node limit was reached before a plan was found (" +
                         std::to_string(options_.node_limit) + " search nodes)";
        break;
      case StoppingLimit::Memory:
        result.limit = "memory";
        result.message = "the memory limit was reached before a plan was found (the search stops at 90% of the "
                         "address space allowed)";
        break;
      case StoppingLimit::None:
        result.message = "the time, node or memory limit was reached before a plan was found";
        break;
    }
  }
}

const char* status_name(PlannerResult::Status status) {
  switch (status) {
    case PlannerResult::Status::Solved: return "solved";
    case PlannerResult::Status::Unsolvable: return "unsolvable";
    case PlannerResult::Status::Exhausted: return "exhausted";
    case PlannerResult::Status::LimitReached: return "limit_reached";
    case PlannerResult::Status::Unsupported: return "unsupported";
    case PlannerResult::Status::InternalError: return "internal_error";
  }
  return "unknown";
}

}  // namespace alplan
