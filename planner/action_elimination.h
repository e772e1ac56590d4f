// Action elimination: a plan found by search may carry actions nothing
// needs (a move undone later, a step the relaxed plan asked for that a later
// choice made useless). This removes them, one action at a time, each time
// rescheduling what is left on its causal order (plan_deordering.h).
//
// Following Nakhost & Muller, "Action elimination and plan neighborhood
// graph search: two algorithms for plan improvement" (ICAPS 2010), greedy
// action elimination, lifted to temporal plans: for each action (its start
// and end snaps together, or an instantaneous step), from the plan's end,
// the action goes with every later step that loses its support: the snaps
// are replayed in the plan's order on their propositional conditions and
// effects, and the first step whose condition fails goes too (with its
// other snap), until none fails (a use-less drop and the pick-up that
// undoes it go together). Derived facts, numbers and conditional effects
// are left to the judge. What is left must still be explained by causal
// links (the deordering, which refuses otherwise, reschedules it) and pass
// `accept`, the caller's validation on the original task. Timed literals
// and the ends of actions running before the plan are never removed (a
// candidate that would need to is dropped).
//
// Safe by construction: only a plan the caller accepted is returned, so a
// plan never gets worse than the one given. The caller must not accept by
// a check looser than the planner's own semantics (temporal_planner.cpp
// validates candidates without VAL's numeric slack as well).
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "planner/plan_deordering.h"
#include "planner/search_engine.h"

namespace alplan {

struct EliminationOptions {
  // Stops between candidates once passed (the result so far is returned).
  SearchDeadline deadline;
  // At most so many candidate plans are rescheduled and judged.
  std::size_t max_candidates = 2000;
};

// The steps to remove with `action_step`'s action: both its snaps and every
// later step (and its other snap) that loses its propositional support;
// nullopt where a timed literal or the end of an action running before the
// plan would have to go, or where the propositional goal is lost.
std::optional<std::vector<bool>> removal_set(const GroundTask& task, const SearchState& start,
                                             const Solution& solution, std::uint32_t action_step);

// The solution without the marked steps, step indices renumbered.
Solution without_steps(const Solution& solution, const std::vector<bool>& removed);

// The plan with every action removed that `accept` allows removing; nullopt
// when none could be. The result's times, steps and makespan are its own;
// final_state and search_makespan are the given plan's (the search's
// measure of it), not recomputed. `accept` judges a rescheduled candidate and says
// whether it replaces the plan so far.
std::optional<Solution> eliminate_actions(const DeorderingInput& input, const Solution& solution,
                                          const std::function<bool(const Solution&)>& accept,
                                          const EliminationOptions& options = {});

}  // namespace alplan
