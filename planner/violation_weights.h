// How a PDDL 3 metric weighs the preferences' violations (Gerevini & Long
// 2005, `is-violated`): what the anytime search may bound by when the
// compiled task reads every violation as 0 (preference_search.h).
#pragma once

#include <optional>
#include <vector>

#include "planner/ground_task.h"

namespace alplan {

// The expression's coefficient on each (is-violated p), p < preferences,
// where it is linear in them with constant coefficients (the rest may be
// anything that reads no violation); nullopt otherwise (a violation
// multiplied by a fluent, divided into, or inside a non-linear term).
std::optional<std::vector<double>> violation_coefficients(const GroundExpression& e, std::size_t preferences);

// Whether the task's metric without its violation terms (the compiled
// task's, pddl3_compilation.cpp) never exceeds the metric with them: a
// minimised metric whose every violation weighs non-negatively. Then the
// compiled metric bounds the true one from below, and the anytime phases
// may prune by the true value of the best plan (up to the witness steps'
// epsilons, where the metric reads total-time). A maximised metric is
// never read so (the search bounds only minimised, monotone metrics).
bool compiled_metric_is_lower_bound(const GroundTask& task);

}  // namespace alplan
