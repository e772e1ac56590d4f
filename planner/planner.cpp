#include "planner/planner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "planner/address_space.h"
#include "planner/evaluation.h"
#include "planner/happening_executor.h"
#include "planner/linear_metric.h"
#include "planner/search_engine.h"
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

// Why an exhausted complete search is not a proof for this task, or "" when
// it is: the search tries only the shortest and longest durations of an
// action whose effects or conditions read ?duration, and with continuous
// change a state holds the values of one schedule among many.
std::string proof_limits(const TaskIndex& index) {
  const GroundTask& task = index.task();
  for (ActionId a = 0; a < task.actions.size(); ++a) {
    if (!task.actions[a].continuous.empty()) {
      return "with continuous change a state holds the values of one schedule among many";
    }
  }
  for (ActionId a = 0; a < task.actions.size(); ++a) {
    if (task.actions[a].durative && index.duration_dependent(a)) {
      return "only the shortest and longest durations of " + task.action_name(task.actions[a]) +
             " (whose effects or conditions read ?duration) were tried";
    }
  }
  return "";
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

bool is_initial(const GroundTask& task, const PlanningStart& start) {
  return start.now == 0.0 && start.running.empty() && start.next_timed_literal == 0 && start.facts == task.initial_facts &&
         start.values == task.initial_values;
}

// Validation of a plan made from an observed state: the executor runs the
// plan as printed (times read back from the text) from that state, with the
// running actions' ends where the schedule put them.
ValidationResult validate_from(const GroundTask& task, const PlanningStart& start, const Solution& solution,
                               const std::vector<ActionId>& actions, const std::string& text, double epsilon) {
  const PlanReadResult printed = read_plan(text, "planner output");
  std::vector<ScheduledStep> steps;
  for (std::size_t i = 0; i < printed.plan.steps.size(); ++i) {
    const PlanStep& p = printed.plan.steps[i];
    ScheduledStep s;
    s.action = actions[i];
    s.step = i;
    s.line = p.line;
    s.start = p.time.value_or(start.now);
    s.duration = p.duration.value_or(0.0);
    s.name = task.action_name(task.actions[s.action]);
    steps.push_back(s);
  }
  for (std::size_t e = 0; e < solution.steps.size(); ++e) {
    const StepRecord& r = solution.steps[e];
    if (r.snap.kind != SnapKind::End || r.start_step != kNoId) continue;
    ScheduledStep s;
    s.action = r.snap.index;
    s.step = steps.size();
    s.started_before = true;
    s.start = start.now;
    s.duration = solution.times[e] - start.now;
    s.name = task.action_name(task.actions[s.action]);
    steps.push_back(s);
  }
  ExecutionStart from;
  for (FactId f : start.facts) from.state.set_fact(f, true);
  for (NumericVarId v = 0; v < start.values.size(); ++v) from.state.set_value(v, start.values[v]);
  from.first_timed_literal = start.next_timed_literal;
  from.now = start.now;
  HappeningExecutor executor(task, ValidatorOptions{epsilon, false});
  return executor.run(steps, printed.plan.steps.size(), from);
}

// A phase of the pipeline: one search, or several taking turns one step
// each (a portfolio in one thread: GBFS and weighted A* fail on different
// problems, and neither knows in advance which it will be).
struct EngineChoice {
  std::string kind;     // ehc, gbfs, wastar
  double weight = 0.0;  // wastar's
  bool deferred = false;  // evaluates nodes when it expands them (or all do, by the options)
  bool typed = false;     // type-based exploration; greedy engines only
  bool novelty = false;   // ordered by (novelty, h); greedy engines only
  bool goal_orders = false;  // prunes states that break the goal orders
  // Misses no plan (SearchSpaceOptions all on, BestFirstOptions::complete):
  // its exhaustion proves that no plan exists, where proving() allows.
  bool complete = false;
};

struct Phase {
  std::vector<EngineChoice> engines;
  std::uint64_t expansion_budget = 0;                    // 0: none
  // Whether weighted A* here may order by the metric. Not in EHC's fallback:
  // it exists to find a first plan at all, and there the metric (a makespan
  // that many steps leave unchanged) guides far worse than step counts
  // (floor-tile 2011 instance 1: 0.08 s by steps, nothing in 20 s by the
  // metric; benchmarks/README.md).
  bool metric_order = true;
  double time_budget = std::numeric_limits<double>::infinity();  // seconds from the phase's start
};

struct PhaseOutcome {
  SearchStatus status = SearchStatus::InProgress;  // InProgress: a limit or the budget
  bool budget_spent = false;
  bool root_dead_end = false;
  std::optional<Solution> solution;
  std::string engine;
  SearchStatistics statistics;
  std::shared_ptr<void> memory;  // the spaces and engines, when the deadline stopped them
};

// Engines refer to their spaces: declared after them, destroyed before.
struct StoppedSearch {
  std::vector<std::unique_ptr<SearchSpace>> spaces;
  std::vector<std::unique_ptr<SearchEngine>> engines;
};

void add(SearchStatistics& into, const SearchStatistics& s) {
  into.expanded += s.expanded;
  into.evaluated += s.evaluated;
  into.generated += s.generated;
  into.duplicates += s.duplicates;
  into.unschedulable += s.unschedulable;
  into.dead_ends += s.dead_ends;
}

// EHC's fallback: engines taking turns one step each. Type-based
// exploration escapes plateaus (promela, sokoban, storage 2014) but its
// random expansions put children the greedy queue then prefers, which lost
// robot-battery p04 (907 expansions for plain GBFS, none found in 3,539 with
// types), so a plain GBFS runs beside the typed one. Deferred evaluation wins
// where children are many and alike (satellite, storage 2014) and loses where
// h must be fresh (benchmarks/README.md).
std::vector<EngineChoice> fallback_engines(const PlannerOptions& options) {
  std::vector<EngineChoice> engines{{"gbfs"}};
  engines.front().goal_orders = options.goal_orders;
  // The typed eager GBFS orders its queues by novelty first, h second
  // (best-first width search): storage 2011 and 2014, depots 4 and
  // parc-printer 5, where every order by h walks into the same dead ends the
  // relaxation cannot see (benchmarks/README.md).
  if (options.type_exploration || options.fallback_novelty) {
    engines.push_back({"gbfs", 0.0, false, options.type_exploration, options.fallback_novelty});
  }
  if (options.fallback_deferred) engines.push_back({"gbfs", 0.0, true, options.type_exploration});
  engines.push_back({"wastar", options.weight});
  return engines;
}

PhaseOutcome run_phase(const Phase& phase, const TaskIndex& index, const SearchStart& start, TemporalRpg& heuristic,
                       const BestFirstOptions& base, const PlannerOptions& options,
                       const std::shared_ptr<const GoalOrders>& orders) {
  std::vector<std::unique_ptr<SearchSpace>> spaces;
  std::vector<std::unique_ptr<SearchEngine>> engines;
  for (const EngineChoice& choice : phase.engines) {
    SearchSpaceOptions space_options;
    if (choice.complete) space_options = {true, true, true};
    spaces.push_back(std::make_unique<SearchSpace>(index, start, options.epsilon, space_options));
    if (choice.goal_orders && orders && !orders->empty()) spaces.back()->prune_by(orders);
    BestFirstOptions bfs = base;
    bfs.weight = choice.weight;
    // GBFS and EHC stay greedy on steps.
    if (choice.kind != "wastar" || !phase.metric_order) bfs.metric = nullptr;
    // Type-based exploration is a greedy search's escape from plateaus and
    // hidden dead ends (Xie et al. 2014); weighted A* keeps its order.
    bfs.type_exploration = choice.typed && choice.kind == "gbfs";
    bfs.deferred = base.deferred || choice.deferred;
    bfs.novelty = choice.novelty && choice.kind == "gbfs";
    bfs.novelty_width = options.novelty_width;
    bfs.complete = choice.complete;
    engines.push_back(choice.kind == "ehc"
                          ? make_enforced_hill_climbing(*spaces.back(), heuristic, true, base.deadline)
                          : make_best_first_search(*spaces.back(), heuristic, bfs));
  }
  PhaseOutcome outcome;
  std::vector<bool> exhausted(engines.size(), false);
  std::size_t left = engines.size();
  bool stopped = false;
  const Clock::time_point began = Clock::now();
  for (std::size_t steps = 0; left > 0; ++steps) {
    // Every step: a step cut short by the deadline has dropped children.
    if (passed(base.deadline)) {
      stopped = true;
      break;
    }
    if ((steps & 15) == 0) {
      std::size_t nodes = 0;
      std::uint64_t expanded = 0;
      for (std::size_t e = 0; e < engines.size(); ++e) {
        nodes += spaces[e]->size();
        expanded += engines[e]->statistics().expanded;
      }
      // A search stopped by a limit keeps its memory (freed when the
      // process ends), whichever limit it was.
      if (nodes > options.node_limit) {
        stopped = true;
        break;
      }
      if (options.address_space_limit && (steps & 255) == 0 && address_space_bytes() > options.address_space_limit) {
        stopped = true;
        break;
      }
      if ((phase.expansion_budget && expanded > phase.expansion_budget) || since(began) > phase.time_budget) {
        outcome.budget_spent = true;
        break;
      }
    }
    const std::size_t e = steps % engines.size();
    if (exhausted[e]) continue;
    const SearchStatus status = engines[e]->step();
    if (status == SearchStatus::Solved) {
      outcome.status = SearchStatus::Solved;
      outcome.solution = engines[e]->solution();
      outcome.engine = engines[e]->name();
      break;
    }
    if (status == SearchStatus::Exhausted) {
      exhausted[e] = true;
      --left;
    }
  }
  if (left == 0) outcome.status = SearchStatus::Exhausted;
  outcome.root_dead_end = spaces.front()->node(spaces.front()->root()).h == std::numeric_limits<double>::infinity();
  for (const auto& engine : engines) add(outcome.statistics, engine->statistics());
  if (stopped) outcome.memory = std::make_shared<StoppedSearch>(StoppedSearch{std::move(spaces), std::move(engines)});
  return outcome;
}

}  // namespace

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

Planner::Planner(std::shared_ptr<const GroundTask> task, PlannerOptions options,
                 std::shared_ptr<PlannerWorkspace> workspace)
    : task_(std::move(task)), options_(std::move(options)), workspace_(std::move(workspace)) {}

PlannerResult Planner::plan(const std::function<void(const FoundPlan&)>& on_plan) {
  return plan_from(initial_start(*task_), on_plan);
}

PlannerResult Planner::plan_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan) {
  return options_.prune_irrelevant ? plan_relevant(start, on_plan) : search_from(start, on_plan);
}

PlannerResult Planner::plan_relevant(const PlanningStart& start,
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
  PlannerResult result = Planner(view.task, options, workspace_).search_from(mapped, on_plan);
  result.times.setup += analysis;
  return result;
}

PlannerResult Planner::search_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan) {
  const Clock::time_point began = Clock::now();
  // The limit counts from here, setup included: a caller's budget is wall time.
  SearchDeadline deadline;
  if (std::isfinite(options_.time_limit)) {
    deadline = began + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(options_.time_limit));
  }
  PlannerResult result;
  const std::shared_ptr<const TaskIndex> shared_index =
      workspace_ && workspace_->index ? std::make_shared<const TaskIndex>(task_, *workspace_->index)
                                      : std::make_shared<const TaskIndex>(task_);
  const TaskIndex& index = *shared_index;
  if (index.unsupported()) {
    result.status = PlannerResult::Status::Unsupported;
    result.message = *index.unsupported();
    return result;
  }
  if (options_.search != "ehc" && options_.search != "gbfs" && options_.search != "wastar") {
    result.status = PlannerResult::Status::Unsupported;
    result.message = "unknown search '" + options_.search + "' (expected ehc, gbfs or wastar)";
    return result;
  }
  if (options_.heuristic != "trpg" && options_.heuristic != "trpg-nohelpful") {
    result.status = PlannerResult::Status::Unsupported;
    result.message = "unknown heuristic '" + options_.heuristic + "' (expected trpg or trpg-nohelpful)";
    return result;
  }
  if (options_.order != "metric" && options_.order != "steps") {
    result.status = PlannerResult::Status::Unsupported;
    result.message = "unknown order '" + options_.order + "' (expected metric or steps)";
    return result;
  }
  if (task_->goal.never) {
    result.status = PlannerResult::Status::Unsolvable;
    result.message = "no plan exists: the goal can never hold (" + *task_->goal.never + ")";
    return result;
  }
  if (const auto clash = clashing_timed_literals(*task_, start.next_timed_literal, options_.epsilon)) {
    result.status = PlannerResult::Status::Unsolvable;
    result.message = "no plan exists: " + *clash;
    return result;
  }
  SearchStart search_start;
  search_start.state = SearchState(task_->facts.size(), start.values);
  for (FactId f : start.facts) search_start.state.set_fact(f, true);
  search_start.state.set_next_timed_literal(start.next_timed_literal);
  search_start.release = start.now;
  if (options_.reserve_planning_time && std::isfinite(options_.time_limit)) search_start.release += options_.time_limit;
  for (const RunningAction& r : start.running) search_start.state.start(r);
  derive(*task_, search_start.state);

  std::optional<LinearMetric> linear = linear_metric(*task_);
  const bool can_prune = !task_->metric || linear;
  // Ordering by the metric needs one that only grows; otherwise the old
  // ordering by steps stays.
  std::shared_ptr<const LinearMetric> order_metric;
  if (options_.order == "metric" && linear) order_metric = std::make_shared<const LinearMetric>(std::move(*linear));
  TemporalRpgOptions heuristic_options;
  heuristic_options.helpful_actions = options_.heuristic == "trpg";
  heuristic_options.resource_balance = options_.resource_balance;
  heuristic_options.count_repetitions = options_.count_repetitions;
  heuristic_options.metric = order_metric;
  TemporalRpg heuristic(index, heuristic_options, workspace_ ? workspace_->graph : nullptr);
  if (workspace_) {
    workspace_->index = shared_index;
    workspace_->graph = heuristic.graph();
  }
  // The goal orders cost an h^2 fixpoint, paid only where an engine prunes
  // with them; from a state with actions running they are not computed (the
  // compressed task has no running actions to start from).
  std::shared_ptr<const GoalOrders> orders;
  if (options_.goal_orders && options_.search == "ehc" && start.running.empty()) {
    GoalOrderOptions order_options;
    order_options.mutexes.deadline = deadline;
    orders = std::make_shared<const GoalOrders>(*task_, start.facts, order_options);
  }
  const bool from_initial = is_initial(*task_, start);
  // Plans from an observed state are checked by validate_from; the plan
  // validator (which grounds the task again for itself) only from the start.
  std::optional<PlanValidator> validator;
  if (from_initial) validator.emplace(task_->lifted, ValidatorOptions{options_.epsilon, false});

  result.times.setup = since(began);

  // One phase after another: the configured search (EHC, under a budget of
  // expansions, falls back to GBFS and weighted A* taking turns), then, in
  // anytime mode, weighted A* with falling weights under a bound.
  std::vector<Phase> pipeline;
  if (options_.search == "ehc") {
    pipeline = {{{{"ehc"}}, options_.ehc_expansions}, {fallback_engines(options_), 0, false}};
    pipeline[0].engines.front().goal_orders = options_.goal_orders;
    // EHC's children are scheduled against a plan that grows with its
    // climb, so its expansions can slow until the budget in expansions is
    // never spent and the fallback never runs (depots, benchmarks/README.md).
    if (std::isfinite(options_.time_limit)) pipeline[0].time_budget = options_.ehc_time_share * options_.time_limit;
  }
  if (options_.search == "gbfs") {
    pipeline = {{{{"gbfs", 0.0, false, options_.type_exploration, options_.novelty}}, 0}};
  }
  if (options_.search == "wastar") pipeline = {{{{"wastar", options_.weight}}, 0}};
  // When EHC and its fallback have exhausted their spaces without a plan, a
  // complete search goes over it again, keeping what they dropped (a
  // guiding dead end the sound relaxation does not confirm, an action run
  // twice at once, a schedule that only looked worse): it finds the plan
  // they missed, or its exhaustion proves there is none.
  std::size_t prover = pipeline.size();
  if (options_.search == "ehc") {
    EngineChoice complete{"wastar", options_.weight};
    complete.complete = true;
    pipeline.push_back({{complete}, 0, false});
  }
  if (options_.anytime) {
    for (double w : {5.0, 3.0, 2.0, 1.5, 1.0}) {
      if (w >= options_.anytime_min_weight) pipeline.push_back({{{"wastar", w}}, options_.anytime_expansions});
    }
  }
  double best_value = std::numeric_limits<double>::infinity();
  bool exhausted_all = true;
  std::string proof;
  // Why an exhausted search is not a proof.
  std::string not_proven = "only incomplete searches ran";
  const Clock::time_point search_began = Clock::now();
  for (std::size_t phase = 0; phase < pipeline.size(); ++phase) {
    if (!options_.anytime && !result.plans.empty()) break;
    const bool fallback = phase == 1 && options_.search == "ehc";
    if ((fallback || phase == prover) && !result.plans.empty()) continue;
    BestFirstOptions bfs;
    bfs.deadline = deadline;
    bfs.metric = order_metric;
    bfs.deferred = options_.deferred_evaluation;
    if (can_prune && !result.plans.empty()) {
      bfs.prune = [&, this](const SearchNode& node) {
        if (!task_->metric) return static_cast<double>(node.depth) >= best_value;
        EvaluationContext context;
        context.total_time = std::max(node.makespan, node.makespan_bound);
        try {
          return evaluate(task_->metric->expression, node.state, context) >= best_value - 1e-9;
        } catch (const EvaluationError&) {
          return false;
        }
      };
    }
    const PhaseOutcome outcome =
        run_phase(pipeline[phase], index, search_start, heuristic, bfs, options_, orders);
    add(result.statistics, outcome.statistics);
    // EHC gave up and the fallback takes over, or an anytime weight gave up
    // and the next one tries.
    if (outcome.budget_spent) continue;
    if (outcome.status == SearchStatus::InProgress) {
      result.search_memory = outcome.memory;
      exhausted_all = false;
      break;  // a limit was reached
    }
    if (outcome.status == SearchStatus::Exhausted) {
      if (outcome.root_dead_end && result.plans.empty()) {
        // A dead root is a proof only if the sound relaxation agrees.
        const PartialPlan root(index, options_.epsilon, search_start.release, search_start.state.running(),
                               search_start.state.values());
        if (heuristic.evaluate(search_start.state, root, Relaxation::Sound).dead_end()) {
          proof = "the goal is unreachable even in the relaxation (temporal relaxed planning graph)";
          std::string facts;
          for (FactId f : heuristic.unreached_goals()) facts += (facts.empty() ? "" : " ") + task_->fact_name(f);
          if (!facts.empty()) proof += ": it never reaches " + facts;
          break;
        }
      }
      const bool complete_search =
          std::any_of(pipeline[phase].engines.begin(), pipeline[phase].engines.end(),
                      [](const EngineChoice& e) { return e.complete; });
      if (complete_search && result.plans.empty()) {
        not_proven = proof_limits(index);
        if (not_proven.empty()) {
          proof = "the search space is exhausted";
          break;
        }
      }
      continue;
    }
    const Clock::time_point validation_began = Clock::now();
    FoundPlan found;
    std::vector<ActionId> actions;
    found.plan = to_plan(*task_, *outcome.solution, &actions);
    found.text = plan_text(found.plan);
    found.engine = outcome.engine;
    found.seconds = since(search_began);
    found.validation = from_initial ? validator->validate(read_plan(found.text, "planner output").plan)
                                    : validate_from(*task_, start, *outcome.solution, actions, found.text,
                                                    options_.epsilon);
    result.times.validation += since(validation_began);
    if (!found.validation.valid) {
      result.status = PlannerResult::Status::InternalError;
      result.message = "the planner produced a plan the validator rejects: " + found.validation.violation->message() +
                       "\n" + found.text;
      return result;
    }
    if (found.validation.value < best_value - 1e-9 || result.plans.empty()) {
      best_value = found.validation.value;
      if (on_plan) on_plan(found);
      result.plans.push_back(std::move(found));
    }
  }
  result.times.search = since(search_began) - result.times.validation;
  if (!result.plans.empty()) {
    result.status = PlannerResult::Status::Solved;
  } else if (!proof.empty()) {
    result.status = PlannerResult::Status::Unsolvable;
    result.message = "no plan exists: " + proof;
  } else if (exhausted_all) {
    result.status = PlannerResult::Status::Exhausted;
    result.message = "the search space is exhausted without a plan; this is not a proof: " + not_proven;
  } else {
    result.status = PlannerResult::Status::LimitReached;
    result.message = "the time, node or memory limit was reached before a plan was found";
  }
  return result;
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
