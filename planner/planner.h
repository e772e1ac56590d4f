// The in-process temporal planner: a POPF/OPTIC-style forward-chaining
// partial-order planner (Coles, Coles, Fox & Long, "Forward-Chaining
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
#include "planner/search_space.h"
#include "planner/task_index.h"
#include "planner/temporal_rpg.h"
#include "planner/validator.h"

namespace alplan {

struct PlannerOptions {
  std::string search = "ehc";      // ehc (falls back to gbfs + wastar), gbfs, wastar
  std::string heuristic = "trpg";  // trpg, or trpg-nohelpful
  double weight = 3.0;             // for wastar, and wastar's turns in the ehc fallback
  // How weighted A* (search "wastar", and the anytime phases) orders its
  // nodes: "metric" (g = the metric so far, h = the metric still to come,
  // for a minimised metric that only grows; other tasks fall back to steps)
  // or "steps" (g = snaps, h = relaxed plan length). GBFS, EHC and the
  // weighted A* taking turns in EHC's fallback are on steps either way.
  // Steps by default: on the baseline suite (20 s, anytime) the metric
  // order improved one first plan, steps ended better on 20 problems and
  // worse on none (benchmarks/README.md).
  std::string order = "steps";
  // EHC gives up after this many expansions (it is incomplete and can wander
  // on plateaus); GBFS and weighted A* then take turns.
  std::uint64_t ehc_expansions = 20000;
  // ... or after this share of the time limit, whichever comes first.
  double ehc_time_share = 0.25;
  // Seconds from the call to plan(), setup and search; checked before every
  // heuristic evaluation, so a large task overruns it by one evaluation.
  double time_limit = std::numeric_limits<double>::infinity();
  std::size_t node_limit = std::numeric_limits<std::size_t>::max();
  // Bytes of address space (planner/address_space.h) past which the search
  // stops as at a limit, its memory handed over unfreed; 0: none. Set below
  // RLIMIT_AS, so a search ends before an allocation is refused.
  std::size_t address_space_limit = 0;
  bool anytime = false;            // keep improving after the first plan
  // Anytime mode runs weighted A* with weights 5, 3, 2, 1.5 and 1 in turn,
  // each bounded by the best plan so far, down to this weight (the lower
  // the weight, the longer it takes to find nothing better).
  double anytime_min_weight = 1.0;
  // With this set, each weight gives up after so many expansions (0: until
  // it finds a better plan or proves there is none). Proving is what costs:
  // most of the time the first plan is not beaten.
  std::uint64_t anytime_expansions = 0;
  double epsilon = 0.001;          // separation of dependent happenings
  // Planning takes time the world does not stop for: with this set, no step
  // starts before now + time_limit, so deadlines (timed literals) shrink by
  // the budget and the plan is still executable when it arrives.
  bool reserve_planning_time = false;
  // Search only the actions that can contribute to the goal
  // (planner/relevance.h); the plans are the same, the heuristic cheaper.
  bool prune_irrelevant = true;
  // GBFS and weighted A* evaluate a node when they expand it, under its
  // parent's h until then (search_engine.h); EHC is unchanged.
  bool deferred_evaluation = false;
  // GBFS also expands every fourth node from a queue drawing at random by
  // (h, g) (planner/type_bucket_queue.h); the draws are seeded, so a run is
  // reproducible. In EHC's fallback the typed GBFS runs beside a plain one
  // (and the deferred GBFS is typed): neither alone solves every problem
  // the pair does (benchmarks/README.md).
  bool type_exploration = true;
  // EHC's fallback runs a GBFS with deferred evaluation as well, all its
  // engines taking turns. Both on since the whole IPC suite gained with them
  // (benchmarks/README.md).
  bool fallback_deferred = true;
  // EHC's fallback's typed eager GBFS orders its queues by novelty within
  // h, then h (planner/novelty_table.h).
  bool fallback_novelty = true;
  // EHC and the plain GBFS of its fallback treat a state that holds a goal
  // which another goal must precede, without that goal, as a dead end
  // (planner/goal_orders.h); the fallback's other engines do not, so the
  // portfolio stays complete.
  bool goal_orders = true;
  // With continuous change: the heuristic counts the producers (recharges,
  // refuels) the relaxed plan's consumption needs (planner/resource_shortfall.h).
  bool resource_balance = true;
  // Without continuous change: an unmet numeric condition counts the
  // repetitions of a constant producer it needs (planner/numeric_relaxation.h).
  bool count_repetitions = true;
  // GBFS orders its queues by (novelty, h), novelty within the node's h
  // (planner/novelty_table.h).
  bool novelty = false;
  // Novelty of facts (1) or of pairs of facts as well (2), for every engine
  // ordered by novelty. 2 solves storage 2011, which 1 does not
  // (benchmarks/README.md).
  int novelty_width = 2;
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
  // Unsolvable is claimed only with a proof: the relaxation fails from the
  // start, or a complete search is exhausted on a task without deadlines
  // (timed initial literals), where ignoring schedules in duplicate
  // detection loses nothing. Otherwise an exhausted search is Exhausted.
  enum class Status { Solved, Unsolvable, Exhausted, LimitReached, Unsupported, InternalError };
  Status status = Status::LimitReached;
  std::vector<FoundPlan> plans;  // each better than the one before; the last is the best
  SearchStatistics statistics;
  SearchPhaseTimes times;
  std::string message;
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
struct PlanningStart {
  double now = 0.0;
  std::vector<FactId> facts;
  std::vector<double> values;
  std::uint32_t next_timed_literal = 0;
  std::vector<RunningAction> running;
};

PlanningStart initial_start(const GroundTask& task);

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

class Planner {
 public:
  Planner(std::shared_ptr<const GroundTask> task, PlannerOptions options,
          std::shared_ptr<PlannerWorkspace> workspace = nullptr);

  // Calls `on_plan` for every improving plan, as soon as it is found.
  PlannerResult plan(const std::function<void(const FoundPlan&)>& on_plan = {});
  PlannerResult plan_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan = {});

 private:
  // plan_from on the relevant actions' view, its ids mapped.
  PlannerResult plan_relevant(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan);
  PlannerResult search_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan);

  std::shared_ptr<const GroundTask> task_;
  PlannerOptions options_;
  std::shared_ptr<PlannerWorkspace> workspace_;
};

// The plan of a solution: one step per instantaneous action and per
// durative action (at its start, with the duration its end gives).
// `actions`, when given, receives the ground action of each plan step.
Plan to_plan(const GroundTask& task, const Solution& solution, std::vector<ActionId>* actions = nullptr);

}  // namespace alplan
