// Plans in the IPC format that OPTIC, POPF and VAL use:
//   12.003: (move robot1 bedroom1 corridor1)  [30.000]
// with `;` comments and blank lines, and sequential plans `(action args)`,
// one step a line. Names are case-insensitive and kept in lower case.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pddl_parser/source_location.h"

namespace alplan {

struct PlanStep {
  std::optional<double> time;  // absent in sequential plans
  std::string action;
  std::vector<std::string> args;
  std::optional<double> duration;
  std::uint32_t line = 0;
};

struct Plan {
  std::vector<PlanStep> steps;
};

struct PlanReadResult {
  Plan plan;
  std::vector<pddl::Diagnostic> diagnostics;
  bool ok() const { return !pddl::has_errors(diagnostics); }
};

PlanReadResult read_plan(std::string_view text, const std::string& file_name);

// A time or duration as the planner prints it: three decimals when it lies
// on the 0.001 grid (as OPTIC prints them), six otherwise, so that VAL reads
// what was scheduled.
std::string format_plan_time(double x);
// The number that text denotes: the value to report wherever a time is
// shown as a number (JSON), without a sum's binary noise (80.00200000000001).
double rounded_plan_time(double x);

// A metric's value, a cost or a makespan as reported beside a plan: ten
// significant digits, enough for times on the 0.001 grid without the binary
// noise of a sum (15.001000000000001).
std::string format_value(double x);

// Seconds of planning as the planner and its CLI report them: to the
// millisecond ("0.012", "1800.000").
std::string format_seconds(double seconds);

// IPC format, times and durations with the given number of decimals.
std::string write_plan(const Plan& plan, int decimals = 3);

// `text` as plan-file comments: every line behind "; ", so that a message
// holding a plan (one the validator rejected) printed beside plans is never
// read as steps. Ends with a newline; "" gives one empty comment line.
std::string plan_comment(std::string_view text);

}  // namespace alplan
