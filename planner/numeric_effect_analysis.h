// What the temporal RPG's interval relaxation of numeric change reads of
// the effects, beyond an increase's sign.
//
// The relaxation (temporal_rpg.h) makes a variable unbounded above once any
// action that can increase it is reachable. Two consequences cost whole
// domains (pathways, benchmarks/README.md):
//  - an action that takes an amount at its start and gives the same amount
//    back at its end (a catalyst, a borrowed unit) was counted as a producer
//    of what it borrows, so borrowing "supplied" every later need;
//  - one application of a producer satisfied any amount: a goal of 4 units
//    made by an action giving 1 counted one action, so the search met a
//    plateau as long as the repetitions.
// give_back() finds the first kind, so the heuristic applies it only to an
// action already running (its taking is in the state). numeric_demand() and
// constant_step() let the relaxed plan count ceil(gap / step) applications
// of a constant producer, the repetition count of Metric-FF's relaxed plans
// (Hoffmann, "The Metric-FF Planning System", JAIR 20, 2003) read off the
// relaxed plan instead of layered numeric graphs. Both only add to h or keep
// values out that no plan reaches: neither makes a reachable goal a dead end.
#pragma once

#include <optional>
#include <vector>

#include "planner/ground_task.h"
#include "planner/search_state.h"

namespace alplan {

// Whether `end` (an effect of g's end) undoes an unconditional effect of
// g's start: the opposite change of the same variable by the same amount,
// an amount that reads no variable (statics are constants after grounding)
// nor any clock, so it is the same at both ends.
bool give_back(const GroundAction& g, const NumericAssignment& end);

// An unmet comparison read as "these variables, summed, must rise (or fall)
// by gap": the left side a variable or a sum of variables, the right side
// reading none. Nothing for any other shape, or one that holds.
struct NumericDemand {
  std::vector<NumericVarId> variables;
  bool upward = true;
  double gap = 0.0;  // > 0
};
std::optional<NumericDemand> numeric_demand(const GroundComparison& c, const SearchState& state);

// The amount by which an action's start and end effects together change v
// in the direction asked, when it is a positive constant; nothing otherwise
// (an assignment, a rate, an amount read from the state or the duration).
std::optional<double> constant_step(const std::vector<const NumericAssignment*>& start,
                                    const std::vector<const NumericAssignment*>& end, NumericVarId v, bool upward);

}  // namespace alplan
