// What a search asks of a heuristic: an estimate of the snaps still needed
// from a state (with the partial plan behind it), the snaps worth trying
// first, and whether the state is a dead end. Heuristics are components
// chosen by a search configuration (search_configuration.h).
#pragma once

#include <limits>
#include <vector>

#include "planner/partial_plan.h"
#include "planner/search_state.h"
#include "planner/snap_action.h"

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

// Which relaxation an evaluation computes (the temporal relaxed planning
// graph's two modes, temporal_rpg.h).
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


class Heuristic {
 public:
  virtual ~Heuristic() = default;
  // `plan` is the partial plan that leads to `state`. A dead end under
  // Relaxation::Sound is a proof; under Guiding it may be a guess.
  virtual HeuristicValue evaluate(const SearchState& state, const PartialPlan& plan,
                                  Relaxation mode = Relaxation::Guiding) = 0;
  // The goal facts the last evaluation never reached (a dead end's reason).
  virtual std::vector<FactId> unreached_goals() const = 0;
};

}  // namespace alplan
