// Which snaps a search state allows, and the state each one leads to. The
// temporal side (can the snap be scheduled?) is the partial plan's job; here
// only the logic of PDDL 2.1 snap actions (Long & Fox 2003; POPF):
// - a start needs its at-start condition now and its over-all condition
//   right after its own effects; its end then becomes available;
// - an end needs its at-end condition;
// - no snap may break the over-all condition of an action still running;
// - timed initial literals are applied in time order;
// - by default an action does not run twice at once (POPF's rule; it keeps
//   symmetric branches out of the search); with `self_overlap` it may, as
//   VAL allows, which a search that must not miss a plan needs (a counter
//   raised by two overlapping runs of one action). Actions with continuous
//   effects never overlap themselves (their schedule tracks one run each);
// - no state breaks a hard PDDL 3 `always` constraint;
// - with `pending_invariants` (a search that must not miss a plan), VAL's
//   happenings are searched as one: a start whose invariant fails opens a
//   happening that other starts and instantaneous actions join until every
//   invariant holds (VAL checks invariants after the happening: two runs of
//   one action whose decreases meet its `(< (x) 0)` only jointly), and an
//   end that breaks running actions' invariants opens one that only their
//   ends join (VAL checks no invariant at its action's end: two actions
//   each deleting at its end what the other needs over all, ending
//   together). By default, as POPF, every invariant holds after each snap.
// Conditions are evaluated exactly (no slack), so plans hold under VAL's
// slightly more lenient comparisons too.
#pragma once

#include <deque>
#include <optional>
#include <vector>

#include "planner/partial_plan.h"
#include "planner/search_state.h"
#include "planner/task_index.h"

namespace alplan {

struct Successor {
  StepRecord step;
  SearchState state;
};

// Duration bounds of an action in a state, from its constraints at `moment`.
struct DurationWindow {
  double min = 0.0;
  double max = kInfiniteDuration;
  bool valid = true;  // false when a bound is undefined or min > max
};

class SuccessorGenerator {
 public:
  explicit SuccessorGenerator(const TaskIndex& index, bool self_overlap = false, bool pending_invariants = false);

  // Every applicable snap: ends of running actions first, then the next
  // timed literal, then starts and instantaneous actions.
  void generate(const SearchState& state, std::vector<Successor>& out) const;

  // The state after a given step, if it is applicable (used for replay).
  std::optional<SearchState> apply(const SearchState& state, const StepRecord& step) const;

  // Whether every running action's over-all condition holds, and every
  // hard PDDL 3 `always` constraint (pddl3_compilation.h): a state that
  // breaks one is in no valid plan, as VAL observes each happening's state.
  bool invariants_hold(const SearchState& state) const { return invariants_hold(state, false); }

  // A start whose invariant fails may still be applied when another start
  // or instantaneous action can give it in the same happening: the state
  // then has an open happening (search_state.h), and its successors are
  // only such snaps, each simultaneous with the opening one, until every
  // invariant holds. An end breaking invariants opens one for their ends.

 private:
  // `except_open`: the invariants of actions started in the open happening
  // are not asked (yet).
  bool invariants_hold(const SearchState& state, bool except_open) const;
  bool always_hold(const SearchState& state) const;
  // Whether the state after a new snap may stand: every invariant holds, or
  // the snap joins (or, as a start whose invariant fails and may be given,
  // opens) a happening. Sets the step's happening.
  bool settle_invariants(const SearchState& before, ActionId started, Successor& s) const;
  // A snap joining the open happening: at its opener's time; the actions
  // outside it keep their invariants (false where one fails); it closes once
  // every invariant holds.
  bool join_open_happening(const SearchState& before, Successor& s) const;
  // Whether every failing part of a just started action's invariant may be
  // given by a start or instantaneous action joining its happening.
  bool may_be_given(ActionId started, const SearchState& before, const SearchState& after) const;
  void add_end(const SearchState& state, std::size_t running_index, std::vector<Successor>& out) const;
  // A zero-duration start is refused where a conditional effect of the
  // action whose condition reads what its other snap writes holds in the
  // state before (TaskIndex::CrossConditionals): VAL's mutex.
  bool zero_duration_conditionals_clear(ActionId id, const SearchState& before) const;
  void add_timed_literal(const SearchState& state, std::vector<Successor>& out) const;
  void add_action(const SearchState& state, ActionId action, std::vector<Successor>& out) const;
  // `quiet`: set to whether no conditional effect fired.
  bool apply_effects(const HappeningEffects& effects, const SearchState& before, double duration,
                     SearchState& after, bool& quiet, const std::vector<std::uint32_t>& skipped = {}) const;
  // A condition's part the state decides: all of it, or with continuous
  // change all but the comparisons on changing values.
  bool condition_holds(const ConditionSet& c, const SearchState& state, double duration) const;
  // Attaches the snap's constraints on changing values; false when a value
  // they need is undefined.
  bool attach_continuous(const GroundAction& action, const SearchState& before, double duration,
                         StepRecord& step) const;

  const TaskIndex& index_;
  bool self_overlap_;
  bool pending_invariants_;  // starts may wait for their happening to give their invariant
  const ContinuousModel* continuous_;  // null without continuous change
  // Per action, its start's duration window when it is the same in every
  // state (constant_duration_window), read instead of evaluated.
  std::vector<std::optional<DurationWindow>> constant_start_window_;
  // The requirements of the hard `always` constraints that simplification
  // did not reduce to true (storage's compatible pairs, for one), checked in
  // every state made.
  std::vector<const ConditionSet*> always_;
  // By fact: the starts and instantaneous actions that add it (also under a
  // condition), that delete it; by numeric variable, that change it.
  std::vector<std::vector<ActionId>> givers_at_start_;
  std::vector<std::vector<ActionId>> takers_at_start_;
  std::vector<std::vector<ActionId>> changers_at_start_;
  // The continuous parts of the steps generated so far, which the steps
  // point to. Only grows, and only with continuous change; generating is
  // otherwise free of side effects.
  mutable std::deque<ContinuousStep> continuous_steps_;
};

// Constraints on continuously changing values are left out (`model`): the
// schedule enforces them.
DurationWindow duration_window(const GroundAction& action, Moment moment, const SearchState& state,
                               const ContinuousModel* model = nullptr);
// The same window, when no constraint at `moment` reads the state: a number
// (most IPC durations, static functions folded in) or a static value the
// problem leaves undefined; none when one reads the state. The relaxation
// asks for every reachable start in every evaluation, so it reads this once.
std::optional<DurationWindow> constant_duration_window(const GroundAction& action, Moment moment);

}  // namespace alplan
