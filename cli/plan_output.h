// What `alplan plan` prints: plans as text (sequential for tasks that read
// no time, planner/sequential_plan.h) and every outcome as JSON in one
// schema, errors included (README: "JSON output").
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

#include "planner/planner.h"

namespace alplan::cli {

// Raised when a field is added, renamed or changes meaning; every object
// `alplan plan --json` prints carries it.
inline constexpr int kPlanJsonSchemaVersion = 1;

// The plan as printed: sequential where the task reads no time, else timed.
std::string printed_plan_text(const GroundTask* task, const FoundPlan& plan);

// One plan: its steps (times as printed, null in a sequential plan), values
// and the text exactly as printed.
nlohmann::json plan_json(const GroundTask* task, const FoundPlan& p, std::size_t index);

// The object every outcome prints, with each field present (null or empty
// where the outcome has none).
nlohmann::json outcome_json(const std::string& status, const std::string& message);

// Input errors (exit 2): the diagnostics, one per line, as printed on stderr.
nlohmann::json input_error_json(const std::string& message, const std::string& diagnostics);

// Seconds as the plan command prints them: milliseconds, no more.
std::string seconds_text(double seconds);

}  // namespace alplan::cli
