// What a validation is asked (VAL's -t and its numeric slack) and what it
// answers: the types the validator (validator.h) and its step-by-step
// executor (happening_executor.h) share, apart from both so that neither
// includes the other; and what an observer of the execution sees.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "planner/explicit_state.h"
#include "planner/formula_evaluation.h"
#include "planner/violation.h"

namespace alplan {

struct ValidatorOptions {
  double epsilon = 0.001;  // VAL's -t: happenings within epsilon/10 merge
  // VAL decides whether (total-time) is a time or a step count from the
  // :durative-actions flag alone, so for a domain with durative actions that
  // omits the flag (IPC 2004 umts) it reports steps + timed literals. We
  // report the makespan; set this to reproduce VAL's number.
  bool val_total_time = false;
  // VAL compares numeric conditions with a slack (formula_evaluation.h), so that
  // `(< x 2)` holds at x = 2. The planner evaluates exactly; a tester that
  // asks whether the planner missed a plan asks with 0.
  double numeric_slack = kNumericSlack;
  // Go on after a violation and list every one found (validator.h says how
  // execution continues). Off, validation stops at the first, as the
  // planner and the monitor need; on or off, `valid` and `violation` are
  // the same.
  bool report_all = false;
};

struct ValidationResult {
  bool valid = false;
  double makespan = 0.0;        // time of the last happening with an action
  std::optional<double> metric;  // the metric's value, when the problem has one
  double value = 0.0;           // VAL's "Final value"
  // The sum of action costs, (total-cost) after the last action happening,
  // when the domain declares it; the metric may weigh it with other terms.
  std::optional<double> total_cost;
  std::optional<Violation> violation;  // the first violation, as it stops validation
  // Every violation found, in plan order, the first being `violation`: with
  // ValidatorOptions::report_all all that validation could find, otherwise
  // that one alone. Empty exactly when the plan is valid.
  std::vector<Violation> violations;
  std::size_t happenings = 0;
  // PDDL 3: violated instances per preference name, as (is-violated name)
  // reads them in the metric.
  std::map<std::string, double> preference_violations;
};

// One executed happening, for a trace (`alplan validate -v`). The states
// are valid only during the observer's call.
struct HappeningRecord {
  std::size_t index = 0;  // 0-based, in time order
  double time = 0.0;
  std::vector<std::string> members;  // "(act args) - start", "(timed initial literal ...)"
  const ExplicitState* before = nullptr;  // as the previous happening left it
  const ExplicitState* after = nullptr;   // after this one, continuous change up to it included
  std::vector<Violation> violations;      // found at this happening
};
using HappeningObserver = std::function<void(const HappeningRecord&)>;

}  // namespace alplan
