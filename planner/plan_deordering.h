// Plan deordering: a plan found by search carries orderings its causal
// structure does not need (the search ordered each snap after the last
// writer of everything it touched, and every write epsilon after the last,
// whatever their polarity). This lifts the plan to the partial order its
// causal links and their threats need, and schedules it again at the
// earliest times that order allows.
//
// Following explanation-based order generalisation (Kambhampati & Kedar,
// "A unified framework for explanation-based generalization of partially
// ordered and partially instantiated plans", Artificial Intelligence 67,
// 1994; Backstrom, "Computational aspects of reordering plans", JAIR 9,
// 1998): each condition of each snap is supported by its earliest achiever
// with no deleter between them in the plan's order (the initial state when
// none deleted it before); a snap that would undo a link is kept before its
// achiever or after its consumer, as the plan had it; an invariant is a link
// protected until its action's end. What the causal view cannot see keeps
// the plan's order: numeric variables (readers and writers, additive writes
// excepted, which commute), conditional effects, facts a derived or complex
// condition reads. Durations stay as scheduled; timed literals stay at their
// times. Happenings then falling at one time that VAL would call a mutex are
// ordered as the plan had them, and the schedule is solved again.
//
// The result is a schedule of the same steps; the caller validates it and
// keeps it only if it is valid and no worse (planner.cpp).
#pragma once

#include <optional>
#include <vector>

#include "planner/search_space.h"
#include "planner/search_state.h"
#include "planner/task_index.h"

namespace alplan {

struct DeorderingInput {
  const TaskIndex& index;
  const SearchState& start;  // the state the plan starts from
  double release = 0.0;      // no new step before this time
  double epsilon = 0.001;
};

// The solution with new times, or nullopt when the plan's causal structure
// could not be explained (then it is kept as it is).
std::optional<Solution> deorder(const DeorderingInput& input, const Solution& solution);

}  // namespace alplan
