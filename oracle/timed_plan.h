// A plan as text reads it, for the reference semantics: the IPC format VAL
// reads (`t: (action args) [d]`, `;` comments) and sequential plans, one
// `(action args)` a line. Written for the oracle alone: it shares no code
// with the planner's plan reader, so a misreading there cannot hide here.
//
// Sequential plans get the times VAL gives them: step k (from 1) at time k,
// which is what VAL's Plan::Plan does for a line without a time.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace alplan::oracle {

struct TimedStep {
  double time = 0.0;
  std::string action;  // lower case
  std::vector<std::string> args;
  std::optional<double> duration;  // absent for an instantaneous step
  int line = 0;
};

struct TimedPlan {
  std::vector<TimedStep> steps;
  bool sequential = false;  // no line carried a time
};

struct TimedPlanRead {
  TimedPlan plan;
  std::string error;  // "line N: ..." when the text is not a plan
  bool ok() const { return error.empty(); }
};

TimedPlanRead read_timed_plan(std::string_view text);

// The IPC format with the given decimals (for the brute force's plans).
std::string write_timed_plan(const TimedPlan& plan, int decimals = 3);

}  // namespace alplan::oracle
