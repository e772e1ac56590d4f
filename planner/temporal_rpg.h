// The temporal relaxed planning graph heuristic of POPF (Coles et al. 2010,
// after CRIKEY's and Sapa's): delete effects are ignored, snap actions are
// reached in order of time (an end no earlier than its start plus the least
// duration), facts that only timed initial literals give are available only
// inside their windows, numeric conditions are relaxed to interval bounds
// (optimistically: a reachable increase makes a variable unbounded above, as
// in Metric-FF's relaxation without its layer counting). A relaxed plan is
// extracted backwards from the goals; its snap count, plus the ends still
// owed by running actions, is h. Its applicable snaps are the helpful ones.
// With continuous change, the producers the relaxed plan's consumption needs
// are added (Sapa's resource adjustment, planner/resource_shortfall.h).
#pragma once

#include <limits>
#include <deque>
#include <memory>
#include <vector>

#include "planner/linear_metric.h"
#include "planner/partial_plan.h"
#include "planner/search_state.h"
#include "planner/task_index.h"

namespace alplan {

struct HeuristicValue {
  double h = std::numeric_limits<double>::infinity();  // infinite: a dead end
  double relaxed_makespan = 0.0;                       // when the goals are reached in the relaxation
  // With a metric in the options: what the relaxed plan's actions, and the
  // ends running actions still owe, add to it.
  double cost = 0.0;
  std::vector<Snap> helpful;
  bool dead_end() const { return h == std::numeric_limits<double>::infinity(); }
};

// Which relaxation an evaluation computes.
// - Sound: a true over-approximation of what any plan from the state can
//   reach, so a goal it never reaches is a proof that the state is a dead
//   end: deletes ignored; facts usable from lower bounds on the times they
//   can be achieved (the epsilon after an achiever is the separation every
//   plan of ours keeps between dependent happenings); windows closed only by
//   timed initial literals, whose times are fixed; a windowed fact's spans
//   as long as its provider's longest duration; an action's own start
//   exempt from the windows of its invariant; an action may start late so
//   that its invariant fits; durations that read changing values taken as
//   0; numeric effects relaxed to interval bounds, a give-back counted as a
//   producer wherever its variable is assigned as well as added to; a
//   running action may start again at once.
// - Guiding (what the search orders by): the same, and a fact a running
//   action's end deletes closes at the latest time that end can come with
//   every other step at its earliest (the steps could move later, so this is
//   a guess, not a bound); a running action starts again only once its run
//   ends; with continuous change, a running action whose invariant must
//   fail before any help can arrive is a dead end. Its dead ends guide and
//   prune the searches that need not be complete; a search that proves must
//   confirm one with the sound relaxation before pruning it.
enum class Relaxation { Guiding, Sound };

struct TemporalRpgOptions {
  bool helpful_actions = true;
  // With continuous change: count the producers the relaxed plan's
  // consumption needs (planner/resource_shortfall.h).
  bool resource_balance = true;
  // Without continuous change: an unmet comparison counts the repetitions
  // of a constant producer it needs (planner/numeric_relaxation.h).
  bool count_repetitions = true;
  // Set: each evaluation also estimates the metric still to come
  // (HeuristicValue::cost), for a search ordered by the metric.
  std::shared_ptr<const LinearMetric> metric;
};

class TemporalRpg {
 public:
  // The relaxed actions, their watchers and the goal: what the heuristic
  // computes once per set of ground actions and goal, before any state.
  struct Graph;

  // With `like` built for a task that shares this index's ground actions,
  // fact table and goal (a GroundingCache's derived task), its graph is
  // shared instead of built again; otherwise it is ignored.
  explicit TemporalRpg(const TaskIndex& index, TemporalRpgOptions options = {},
                       std::shared_ptr<const Graph> like = nullptr);
  ~TemporalRpg();
  TemporalRpg(const TemporalRpg&) = delete;
  TemporalRpg& operator=(const TemporalRpg&) = delete;

  // `plan` is the partial plan that leads to `state`, for the times at which
  // its facts became true and its running actions started.
  HeuristicValue evaluate(const SearchState& state, const PartialPlan& plan,
                          Relaxation mode = Relaxation::Guiding);
  // The goal facts the last evaluation never reached (a dead end's reason).
  std::vector<FactId> unreached_goals() const;
  const std::shared_ptr<const Graph>& graph() const { return graph_; }
  static std::shared_ptr<const Graph> graph_for(const TaskIndex& index) { return build(index); }

 private:
  struct RelaxedAction {
    std::vector<FactId> start_pre, end_pre;
    std::vector<std::uint32_t> start_numeric, end_numeric;  // indices into comparisons_
    std::vector<FactId> start_add, end_add;
    // The over-all and at-end facts whose windows the action must fit: those
    // its own start does not give (an action holding what it gives itself
    // at start needs no one else's window for it).
    std::vector<FactId> held_over_all, held_at_end;
    std::vector<const NumericAssignment*> start_numeric_effects, end_numeric_effects;
    // End effects that give back what the start took (a catalyst, a borrowed
    // tool count): net zero, so applied only for an action already running
    // in the state, whose taking the state holds. Counted as producers they
    // made the variable unbounded (pathways, benchmarks/README.md).
    std::vector<const NumericAssignment*> end_returns;
    bool durative = false;
    // The start's minimum duration when no duration constraint reads the
    // state, -1 when they admit none; NaN when a constraint reads a value
    // actions change: the relaxation then takes 0, the only lower bound
    // that holds in every state the plan may reach before the start.
    double fixed_duration = std::numeric_limits<double>::quiet_NaN();
  };
  struct Event {
    double time;
    FactId fact;
    // Ties go to the lower fact id, so that equal alternatives are chosen in
    // the order the task declares them, whatever the heap does.
    bool operator>(const Event& other) const {
      return time > other.time || (time == other.time && fact > other.fact);
    }
  };
  enum class AchieverKind : unsigned char { None, State, Start, End, Instant, TimedLiteral, Axiom };
  struct Achiever {
    AchieverKind kind = AchieverKind::None;
    std::uint32_t index = 0;
  };
  class Exploration;
  friend class Exploration;

  static std::shared_ptr<const Graph> build(const TaskIndex& index);
  static bool fits(const Graph& graph, const GroundTask& task);

  const TaskIndex& index_;
  TemporalRpgOptions options_;
  std::shared_ptr<const Graph> graph_;
  // The graph's parts, by the names the exploration reads them.
  const std::vector<RelaxedAction>& actions_;
  const std::vector<const GroundComparison*>& comparisons_;
  const std::vector<std::vector<ActionId>>& start_watchers_;
  const std::vector<std::vector<ActionId>>& end_watchers_;
  const std::vector<std::vector<std::uint32_t>>& axiom_watchers_;
  const std::vector<std::vector<ActionId>>& numeric_watchers_;
  const std::vector<std::vector<NumericVarId>>& comparison_variables_;
  const std::vector<FactId>& goal_facts_;
  const std::vector<std::uint32_t>& goal_numeric_;
  std::unique_ptr<Exploration> exploration_;  // working memory, reused
};

struct TemporalRpg::Graph {
  std::shared_ptr<const GroundTask> task;  // keeps the actions and goal the pointers below point into
  std::vector<RelaxedAction> actions;
  std::vector<const GroundComparison*> comparisons;
  std::vector<std::vector<ActionId>> start_watchers, end_watchers;  // by fact
  std::vector<std::vector<std::uint32_t>> axiom_watchers;            // by fact
  std::vector<std::vector<ActionId>> numeric_watchers;                // by variable
  std::vector<std::vector<NumericVarId>> comparison_variables;
  std::vector<FactId> goal_facts;  // sorted
  std::vector<std::uint32_t> goal_numeric;
  // Continuous effects relaxed to an increase or decrease at the start by
  // their rate (the relaxation only reads its sign); a deque, so that the
  // actions' pointers into it stay valid.
  std::deque<NumericAssignment> continuous_effects;
};

}  // namespace alplan
