// A metric to minimise that can only grow as a plan grows, read as what it
// is: a constant plus non-negative multiples of (total-time) and of fluents
// that actions only increase by non-negative constants. Anytime search
// prunes on such a metric (a partial plan already at the best value cannot
// lead to a better one), and weighted A* can order its nodes by it (g = the
// metric so far, h = the metric still to come) instead of by step counts.
#pragma once

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "planner/ground_task.h"
#include "planner/search_state.h"

namespace alplan {

struct LinearMetric {
  double constant = 0.0;
  double time_weight = 0.0;                                // of (total-time)
  std::vector<std::pair<NumericVarId, double>> variables;  // weight of each fluent, summed per variable
  // What each ground action adds to the metric at its start and at its end,
  // through its unconditional effects only: a conditional effect may not
  // fire, and an estimate that counts it could overrate an action.
  std::vector<double> start_cost, end_cost;

  // The metric's value in a state reached at `makespan` (an undefined fluent
  // counts as 0, as VAL starts an increased undefined value at 0).
  double value(const SearchState& state, double makespan) const;
  // The metric still to come: the relaxed plan's cost, and the time between
  // the node's makespan and the relaxed plan's lower bound on it.
  double remaining(double relaxed_cost, double makespan, double makespan_bound) const {
    return relaxed_cost + time_weight * std::max(0.0, makespan_bound - makespan);
  }
};

// A metric's value read so that smaller is better: a maximised metric's
// negated (no metric: the value as it is, a length or makespan).
double minimised(const GroundTask& task, double value);

// The task's metric in this form, when it is minimised and monotone; nullopt
// when there is no metric, it is maximised, or it can shrink as a plan grows.
std::optional<LinearMetric> linear_metric(const GroundTask& task);

}  // namespace alplan
