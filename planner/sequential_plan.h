// Plans of classical tasks in the form users of classical planners expect
// (Fast Downward's `sas_plan`, the IPC classical tracks): one step a line,
// no timestamps, then `; cost = N (unit cost)`, `(general cost)` with
// action costs, or `(metric)`, the metric's value without them. VAL
// reads such a plan as one happening per step, in order.
//
// The planner schedules every task on the time line (0.000, 0.001, ...).
// A task is printed sequentially only when nothing in it reads time: no
// durative action, no timed literal; and only when the sequential text,
// validated again, is valid with the same value. So a plan printed this way
// is one the validator accepted in the form printed (a metric reading
// total-time, for one, counts steps there, and the timed form is kept).
#pragma once

#include <optional>
#include <string>

#include "planner/temporal_planner.h"

namespace alplan {

// Whether the task reads no time: no durative action, no timed literal.
bool reads_no_time(const GroundTask& task);

// The plan as a sequential plan with its cost line, or nullopt when the task
// reads time or the sequential form is not valid with the same value.
std::optional<std::string> sequential_plan_text(const GroundTask& task, const FoundPlan& plan);

}  // namespace alplan
