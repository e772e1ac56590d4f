// What `alplan plan` prints: plans as text (sequential for tasks that read
// no time, planner/sequential_plan.h) and every outcome as JSON in one
// schema, errors included (README: "alplan plan", `--json`).
#pragma once

#include <nlohmann/json.hpp>

#include <map>
#include <string>

#include "planner/planner.h"

namespace alplan::cli {

// Raised when a field is added, renamed or changes meaning; every object
// `alplan plan --json` prints carries it.
inline constexpr int kPlanJsonSchemaVersion = 1;

struct PrintedPlan {
  std::string text;
  bool sequential = false;  // no timestamps, a cost line
};

// Each plan in the form printed, worked out once (a sequential form is
// validated again, which grounds the task for the validator).
class PlanPrinter {
 public:
  explicit PlanPrinter(const GroundTask* task) : task_(task) {}
  const PrintedPlan& printed(const FoundPlan& plan);

 private:
  const GroundTask* task_;
  std::map<std::string, PrintedPlan> by_text_;
};

// One plan: its steps (times as printed, null in a sequential plan), values
// and the text exactly as printed.
nlohmann::json plan_json(const FoundPlan& p, const PrintedPlan& printed, std::size_t index);

// The object every outcome prints, with each field present (null or empty
// where the outcome has none); `diagnostics` are the input's errors and
// warnings as printed on stderr, one a line.
nlohmann::json outcome_json(const std::string& status, const std::string& message,
                            const std::string& diagnostics = "");

}  // namespace alplan::cli
