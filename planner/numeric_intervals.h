// The numeric part of the temporal relaxation: each variable's value is
// relaxed to an interval that only widens (Metric-FF's relaxation without
// its layer counting). An increase that can be positive makes a variable
// unbounded above, a decrease unbounded below, an assignment joins its value
// in; a comparison holds when its intervals admit it. Since the intervals
// only widen, a comparison that fails on them fails in every state the
// relaxation stands for.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "planner/continuous_change.h"
#include "planner/ground_task.h"
#include "planner/partial_plan.h"
#include "planner/search_state.h"

namespace alplan {

struct Interval {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool undefined() const { return lo > hi; }
};

class NumericIntervals {
 public:
  explicit NumericIntervals(std::size_t variables);

  // The state's values; with continuous change, where a condition needs it,
  // a changing variable's range over every schedule the plan allows.
  void reset(const SearchState& state, const PartialPlan& plan, const ContinuousModel* continuous);

  Interval interval(const GroundExpression& e) const;
  bool satisfiable(const GroundComparison& comparison) const;
  // Widens a variable's interval by an effect; true when it changed. The
  // first action to raise a variable's upper bound is its supporter upward,
  // the first to lower its lower bound its supporter downward (Metric-FF's
  // achievers by direction: a synthesis that uses up some of a catalyst is
  // no support for a condition that wants more of it, pathways).
  bool apply(const NumericAssignment& effect, ActionId source);

  ActionId supporter(NumericVarId v, bool upward) const { return upward ? up_[v] : down_[v]; }
  // The first action to widen the variable either way (where a condition's
  // direction is not known: an equality, a product).
  ActionId first_supporter(NumericVarId v) const { return first_[v]; }
  // A changing variable's greatest value now, where the reset asked the
  // schedule for it; NaN elsewhere.
  double greatest_now(NumericVarId v) const { return greatest_now_[v]; }

 private:
  std::vector<Interval> bounds_;
  std::vector<double> greatest_now_;
  std::vector<ActionId> up_, down_, first_;  // supporters by direction, and either way
  // Changes of each variable in this evaluation: past kWidenAfter, a change
  // widens it to everything (an assignment cycle, x := y + 1 and y := x + 1,
  // would otherwise widen it by one a round for ever).
  std::vector<std::uint32_t> changes_;
  static constexpr std::uint32_t kWidenAfter = 16;
};

}  // namespace alplan
