// The in-process temporal planner's search core, below the front door
// (planner.h, which sends PDDL 3 tasks through preference_search.h first):
// a POPF/OPTIC-style forward-chaining partial-order planner (Coles, Coles, Fox & Long, "Forward-Chaining
// Partial-Order Planning", ICAPS 2010; OPTIC, ICAPS 2012) with a temporal
// relaxed planning graph heuristic, enforced hill-climbing falling back to
// best-first search, and an anytime mode.
//
// Contract: plan() returns only plans our validator (VAL's semantics)
// accepts as printed; an invalid plan is a bug and is reported as
// Status::InternalError, never returned as a plan. No mutable global state:
// planners may run in several threads at once.
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/ground_task.h"
#include "planner/plan.h"
#include "planner/relevance.h"
#include "planner/search_configuration.h"
#include "planner/search_pipeline.h"
#include "planner/search_space.h"
#include "planner/task_index.h"
#include "planner/temporal_rpg.h"
#include "planner/validator.h"

namespace alplan {

struct FoundPlan;

struct PlannerOptions {
  // What searches, with which heuristics and pruning, in which order
  // (search_configuration.h): the `default` alias unless set.
  SearchConfiguration search = alias("default");
  // Seconds from the call to plan(), setup and search; checked before every
  // heuristic evaluation, so a large task overruns it by one evaluation.
  double time_limit = std::numeric_limits<double>::infinity();
  std::size_t node_limit = std::numeric_limits<std::size_t>::max();
  // Bytes of address space (planner/address_space.h) past which the search
  // stops as at a limit, its memory handed over unfreed; 0: none. Set below
  // RLIMIT_AS, so a search ends before an allocation is refused.
  std::size_t address_space_limit = 0;
  double epsilon = 0.001;          // separation of dependent happenings
  // VAL's -t, which every plan is validated against: happenings within a
  // tenth of it are one happening.
  double tolerance = 0.001;
  // When no plan exists with dependent happenings `epsilon` apart, search
  // once more with them only just over a tenth of `tolerance` apart (what
  // VAL needs to see two happenings): a plan found then is valid, and an
  // exhausted search then is a proof for every plan VAL would separate
  // (planner/README.md, "When the planner says no plan exists").
  bool close_gap_fallback = true;
  // Planning takes time the world does not stop for: with this set, no step
  // starts before now + time_limit, so deadlines (timed literals) shrink by
  // the budget and the plan is still executable when it arrives.
  bool reserve_planning_time = false;
  // Search only the actions that can contribute to the goal
  // (planner/relevance.h); the plans are the same, the heuristic cheaper.
  bool prune_irrelevant = true;
  // Lift each plan to the partial order its causal links need and schedule
  // it again (planner/plan_deordering.h); kept when valid and no worse.
  bool deorder = true;
  // Then remove, one at a time, actions the plan is valid and no worse
  // without (planner/action_elimination.h); only with deorder, whose
  // causal explanation it reschedules by.
  bool eliminate_actions = true;
  // Validate plans with the ground task's own executor instead of grounding
  // its lifted task again: for a task a pass derived (pddl3_compilation.h),
  // whose lifted task only names the actions the pass added.
  bool validate_ground = false;
  // What the caller optimises, where it is not the task's metric alone (a
  // PDDL 3 task compiled without its violation terms, preference_search.h).
  struct Objective {
    // Each plan found, smaller better (a maximised metric negated); plans
    // are handed on only when it improves; nullopt stops the search.
    std::function<std::optional<double>(const FoundPlan&)> value;
    // The task's metric (minimised) never exceeds `value` on any plan: the
    // anytime phases then prune the nodes whose metric so far and still to
    // come cannot beat the best value, which keeps every better plan.
    bool metric_is_lower_bound = false;
  };
  Objective objective;
};

struct FoundPlan {
  Plan plan;
  std::string text;              // IPC format, exactly as validated
  ValidationResult validation;
  double seconds = 0.0;          // since the search began
  std::string engine;
};

struct SearchPhaseTimes {
  double setup = 0.0, search = 0.0, validation = 0.0;
};

struct PlannerResult {
  // Unsolvable is claimed only with a proof: the goal is grounded away, the
  // timed literals clash, the sound relaxation fails from the start, or a
  // complete search (search_configuration.h) is exhausted where nothing in
  // the task keeps that from being a proof. Otherwise an exhausted search is
  // Exhausted, and the message says why it proves nothing.
  enum class Status { Solved, Unsolvable, Exhausted, LimitReached, Unsupported, InternalError };
  Status status = Status::LimitReached;
  std::vector<FoundPlan> plans;  // each better than the one before; the last is the best
  SearchStatistics statistics;
  SearchPhaseTimes times;
  std::string message;
  // With LimitReached: which limit, "time", "nodes" or "memory" (empty when
  // a preference round or another caller could not tell).
  std::string limit;
  // The search the time limit stopped, handed over instead of freed:
  // freeing a million nodes one by one takes seconds (6.9 s for 1.1 million
  // on pathways, where the limit was 40 s), which would overrun the limit.
  // Freed with the result; a process that is about to end may keep it.
  std::shared_ptr<void> search_memory;

  const FoundPlan* best() const { return plans.empty() ? nullptr : &plans.back(); }
};

// The status as `alplan plan --json` and the Python module name it
// (solved, unsolvable, exhausted, limit_reached, unsupported, internal_error).
const char* status_name(PlannerResult::Status status);

// Where to plan from: the task's initial state, or a state observed at time
// `now` with actions still running (the monitor passes these). Time stays
// the task's time: new steps come at or after `now`, timed literals from
// `next_timed_literal` on keep their times (earlier ones are past), and a
// running action (start_step kNoId) ends within [min_duration,
// max_duration] of time 0 — that is, the bounds are absolute end times.
//
// PDDL 3 constraints judge the whole trajectory, so a plan from an observed
// state is judged with the states seen before it: `history`, oldest first,
// each at its time (before `now`). A `sometime` or `within` met there needs
// nothing more, a constraint violated there stays violated (a hard one makes
// the task unsolvable from here, and that is a proof), and `within` and
// `hold-during` deadlines keep their absolute times. With no history the
// observed state is the trajectory's first.
struct ObservedState {
  double time = 0.0;
  std::vector<FactId> facts;
  std::vector<double> values;
};

struct PlanningStart {
  double now = 0.0;
  std::vector<FactId> facts;
  std::vector<double> values;
  std::uint32_t next_timed_literal = 0;
  std::vector<RunningAction> running;
  std::vector<ObservedState> history;
};

PlanningStart initial_start(const GroundTask& task);
// Whether `start` is the task's initial state at time 0, nothing before it.
bool is_initial_start(const GroundTask& task, const PlanningStart& start);

class TrajectoryMonitor;

// A plan printed for `start`, validated from that state by the validator's
// executor (times as printed): `actions` are its steps' ground actions, in
// order; `running_ends` the actions running at the start, with when each
// ends; `trajectory` the PDDL 3 monitor of the states before it, carried on
// (null: the trajectory starts here).
ValidationResult validate_printed_from(const GroundTask& task, const PlanningStart& start, const Plan& printed,
                                       const std::vector<ActionId>& actions,
                                       const std::vector<std::pair<ActionId, double>>& running_ends, double epsilon,
                                       std::shared_ptr<const TrajectoryMonitor> trajectory = nullptr);

// What a planner builds for its task before it searches (the task index,
// the relaxed planning graph), kept by a caller who plans again and again on
// tasks that share their ground actions (a GroundingCache's derived tasks),
// so that the next planner reuses what still fits. One per execution: a
// planner writes what it built back into it.
struct PlannerWorkspace {
  std::shared_ptr<const TaskIndex> index;
  std::shared_ptr<const TemporalRpg::Graph> graph;
  // The relevant actions of the last task planned on, for tasks that share
  // its ground actions and goal; `kept` were kept whatever they do.
  struct Relevance {
    SharedVector<GroundAction> source;
    std::vector<FactId> goal_positive, goal_negative;
    std::vector<ActionId> kept;
    RelevantView view;
  };
  std::shared_ptr<const Relevance> relevance;
};

// Builds the workspace for a task ahead of planning, on its relevant actions
// unless `prune_irrelevant` is off (a monitor does it when execution
// starts, so that a repair finds it ready).
PlannerWorkspace prepare_workspace(std::shared_ptr<const GroundTask> task, bool prune_irrelevant = true);

class TemporalPlanner {
 public:
  TemporalPlanner(std::shared_ptr<const GroundTask> task, PlannerOptions options,
                  std::shared_ptr<PlannerWorkspace> workspace = nullptr);

  // Calls `on_plan` for every improving plan, as soon as it is found. The
  // task's PDDL 3 beyond hard `always` must have been compiled away
  // (pddl3_compilation.h; Planner does it).
  PlannerResult plan(const std::function<void(const FoundPlan&)>& on_plan = {});
  PlannerResult plan_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan = {});

 private:
  // plan_from on the relevant actions' view, its ids mapped.
  PlannerResult plan_relevant(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan);
  PlannerResult search_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan);
  // One search at options_.epsilon; `by_search` says whether an
  // Unsolvable it returns rests on an exhausted search.
  PlannerResult search_once(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan,
                            bool& by_search);
  // After a search at epsilon found nothing: the same search with
  // happenings closer together (PlannerOptions::close_gap_fallback).
  PlannerResult search_closer(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan,
                              PlannerResult first, double elapsed);
  std::optional<PlannerResult> refused(const TaskIndex& index, const PlanningStart& start) const;
  void finish(PlannerResult& result, const PipelineOutcome& outcome) const;

  std::shared_ptr<const GroundTask> task_;
  PlannerOptions options_;
  std::shared_ptr<PlannerWorkspace> workspace_;
};

// The plan of a solution: one step per instantaneous action and per
// durative action (at its start, with the duration its end gives).
// `actions`, when given, receives the ground action of each plan step.
Plan to_plan(const GroundTask& task, const Solution& solution, std::vector<ActionId>* actions = nullptr);

}  // namespace alplan
