// The temporal relaxed planning graph's per-evaluation work (temporal_rpg.h),
// in two parts with one concern each: the exploration forward in time from a
// state (which facts and actions are reached, and when), and the relaxed
// plan extracted backwards from the goals. The numeric part of the
// relaxation is numeric_intervals.h, the windows of facts fact_windows.h.
// Internal to the heuristic: temporal_rpg.cpp and relaxed_plan.cpp only.
#pragma once

#include <initializer_list>
#include <optional>
#include <queue>
#include <vector>

#include "planner/fact_windows.h"
#include "planner/numeric_intervals.h"
#include "planner/resource_shortfall.h"
#include "planner/temporal_rpg.h"

namespace alplan {

// An array whose entries reset to a fallback when first touched in a new
// generation: nothing is cleared between evaluations (the arrays are as long
// as the task has actions and facts).
template <typename T>
struct Stamped {
  std::vector<T> values;
  std::vector<std::uint32_t> stamps;
  T fallback{};
  void resize(std::size_t n, T initial) {
    values.assign(n, initial);
    stamps.assign(n, 0);
    fallback = initial;
  }
  T& at(std::size_t i, std::uint32_t generation) {
    if (stamps[i] != generation) {
      stamps[i] = generation;
      values[i] = fallback;
    }
    return values[i];
  }
  bool set_in(std::size_t i, std::uint32_t generation) const { return stamps[i] == generation && values[i]; }
};

// The relaxed plan, extracted backwards from the goals over an exploration:
// each goal's achiever, its preconditions' achievers, and so on; windowed
// facts held over all from a provider long enough; repetitions of constant
// producers an unmet comparison asks; with continuous change the producers
// the consumption needs. Its snap count, plus the ends running actions
// still owe, is h; its snaps applicable now are the helpful ones.
class RelaxedPlan {
 public:
  explicit RelaxedPlan(TemporalRpg::Exploration& exploration) : x_(exploration) {}
  void resize(std::size_t actions);
  HeuristicValue extract(const SearchState& state, double goal_time);
  // With continuous change, after extract: a running action whose
  // invariant must fail before any help can arrive (guiding only).
  bool continuous_dead_end(HeuristicValue& value);

 private:
  void add_helpful(const SearchState& state, HeuristicValue& value);
  void note_repetitions(std::uint32_t comparison, const SearchState& state);
  std::vector<ActionId> shortfall_producers(const SearchState& state, double& extra);
  void need_numeric(const std::vector<std::uint32_t>& comparisons);
  void count_start(ActionId a);
  void count_end(ActionId a);
  void count_action(ActionId a);
  void drain();

  TemporalRpg::Exploration& x_;
  // The extraction under way.
  const SearchState* state_ = nullptr;
  const LinearMetric* metric_ = nullptr;
  HeuristicValue value_;
  double count_ = 0.0;
  std::vector<FactId> open_;       // facts to support
  std::vector<ActionId> support_;  // actions to count (numeric supporters, span providers)
  Stamped<char> counted_start_, counted_end_;
  std::vector<std::pair<ActionId, double>> repetitions_;  // producer, applications asked
  std::vector<NumericVarId> short_variables_;  // the last extraction's, whose producers it counted
};

class TemporalRpg::Exploration {
 public:
  explicit Exploration(TemporalRpg& rpg);
  HeuristicValue run(const SearchState& state, const PartialPlan& plan, Relaxation mode);

 private:
  friend class TemporalRpg;
  friend class RelaxedPlan;

  void reach(FactId f, double time, Achiever achiever, double cost);
  double cost_of(const std::vector<FactId>& facts);
  void process(FactId f, double time);
  // Takes the earliest event off the queue and processes it; false when it
  // was stale.
  bool process_next();
  void try_start(ActionId a, double time);
  void try_end(ActionId a);
  void apply_numeric(const std::vector<const NumericAssignment*>& effects, ActionId source);
  bool satisfiable(const std::vector<std::uint32_t>& comparisons) const;
  void park(FactId fact, ActionId a, bool end);
  void park_on_windows(ActionId a, bool end, std::initializer_list<const std::vector<FactId>*> lists);
  double duration_of(ActionId a);
  void start_counters(const SearchState& state, const PartialPlan& plan);
  void seed(const SearchState& state, const PartialPlan& plan);
  bool goals_reached() const { return goals_left_ == 0 && satisfiable(rpg_.goal_numeric_); }
  // How long after its achiever a fact is usable. The guiding relaxation
  // keeps the search's epsilon; the sound one none: VAL needs only more than
  // a tenth of its tolerance between dependent happenings, and an invariant
  // may start with its achiever, so any positive gap could close a window a
  // real plan fits.
  double gap() const { return mode_ == Relaxation::Sound ? 0.0 : plan_->epsilon(); }

  TemporalRpg& rpg_;
  Relaxation mode_ = Relaxation::Guiding;
  const ContinuousModel* continuous_;  // null without continuous change: read once, not per action
  const SearchState* state_ = nullptr;
  const PartialPlan* plan_ = nullptr;
  std::uint32_t generation_ = 0;
  Stamped<double> fact_time_, fact_cost_, end_ready_, enabled_time_, started_at_, start_cost_;
  Stamped<double> start_time_;  // infinite until started in this evaluation
  Stamped<Achiever> achiever_;
  Stamped<std::uint32_t> start_count_, end_count_, axiom_count_;
  Stamped<char> processed_, parked_start_, parked_end_;
  Stamped<char> ended_;  // the end was reached (its effects applied)
  // The state's running actions, as a lookup: SearchState::is_running scans
  // its list, and try_end asks for every end the exploration reaches.
  Stamped<char> running_;
  NumericIntervals numeric_;
  std::optional<ResourceBalance> balance_;
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> queue_;
  std::size_t goals_left_ = 0;
  FactWindows windows_;
  // Actions waiting for a fact whose windows do not fit them to be achieved
  // again by an action (then it is usable for good).
  std::vector<std::vector<std::pair<ActionId, bool>>> parked_on_;
  std::vector<FactId> parked_facts_;
  RelaxedPlan relaxed_plan_;
};

}  // namespace alplan
