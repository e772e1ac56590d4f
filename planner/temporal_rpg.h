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

#include "planner/heuristic.h"
#include "planner/linear_metric.h"
#include "planner/partial_plan.h"
#include "planner/search_state.h"
#include "planner/task_index.h"

namespace alplan {

struct TemporalRpgOptions {
  bool helpful_actions = true;
  // With continuous change: count the producers the relaxed plan's
  // consumption needs (planner/resource_shortfall.h).
  bool resource_balance = true;
  // Without continuous change: an unmet comparison counts the repetitions
  // of a constant producer it needs (planner/numeric_effect_analysis.h).
  bool count_repetitions = true;
  // Set: each evaluation also estimates the metric still to come
  // (HeuristicValue::cost), for a search ordered by the metric.
  std::shared_ptr<const LinearMetric> metric;
};

class TemporalRpg : public Heuristic {
 public:
  // The relaxed actions, their watchers and the goal: what the heuristic
  // computes once per set of ground actions and goal, before any state.
  struct Graph;

  // With `like` built for a task that shares this index's ground actions,
  // fact table and goal (a GroundingCache's derived task), its graph is
  // shared instead of built again; otherwise it is ignored.
  explicit TemporalRpg(const TaskIndex& index, TemporalRpgOptions options = {},
                       std::shared_ptr<const Graph> like = nullptr);
  ~TemporalRpg() override;
  TemporalRpg(const TemporalRpg&) = delete;
  TemporalRpg& operator=(const TemporalRpg&) = delete;

  // `plan` is the partial plan that leads to `state`, for the times at which
  // its facts became true and its running actions started.
  HeuristicValue evaluate(const SearchState& state, const PartialPlan& plan,
                          Relaxation mode = Relaxation::Guiding) override;
  // The goal facts the last evaluation never reached (a dead end's reason).
  std::vector<FactId> unreached_goals() const override;
  const std::shared_ptr<const Graph>& graph() const { return graph_; }
  static std::shared_ptr<const Graph> graph_for(const TaskIndex& index) { return build(index); }

 private:
  struct RelaxedAction {
    std::vector<FactId> start_pre, end_pre;
    // What the sound relaxation waits for before a start: its at-start
    // facts only. An invariant may come from another start in the same
    // happening, and what the end needs waits for the end.
    std::vector<FactId> sound_start_pre;
    std::vector<std::uint32_t> sound_start_numeric, sound_end_numeric;
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
  friend class RelaxedPlan;

  static std::shared_ptr<const Graph> build(const TaskIndex& index);
  static bool fits(const Graph& graph, const GroundTask& task);

  const TaskIndex& index_;
  TemporalRpgOptions options_;
  std::shared_ptr<const Graph> graph_;
  // The graph's parts, by the names the exploration reads them.
  const std::vector<RelaxedAction>& actions_;
  const std::vector<const GroundComparison*>& comparisons_;
  const std::vector<std::vector<ActionId>>& start_watchers_;
  const std::vector<std::vector<ActionId>>& sound_start_watchers_;
  const std::vector<std::vector<ActionId>>& end_watchers_;
  const std::vector<std::vector<std::uint32_t>>& axiom_watchers_;
  const std::vector<std::vector<ActionId>>& numeric_watchers_;
  const std::vector<std::vector<std::pair<ActionId, bool>>>& amount_readers_;
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
  std::vector<std::vector<ActionId>> sound_start_watchers;           // by fact
  std::vector<std::vector<std::uint32_t>> axiom_watchers;            // by fact
  std::vector<std::vector<ActionId>> numeric_watchers;                // by variable
  // By variable: the snaps whose numeric effects read it in their amounts
  // ((increase (x) (y)) reads y), as (action, end?): when the variable
  // widens, their effects apply again with the wider amount.
  std::vector<std::vector<std::pair<ActionId, bool>>> amount_readers;
  std::vector<std::vector<NumericVarId>> comparison_variables;
  std::vector<FactId> goal_facts;  // sorted
  std::vector<std::uint32_t> goal_numeric;
  // Continuous effects relaxed to an increase or decrease at the start by
  // their rate (the relaxation only reads its sign); a deque, so that the
  // actions' pointers into it stay valid.
  std::deque<NumericAssignment> continuous_effects;
};

}  // namespace alplan
