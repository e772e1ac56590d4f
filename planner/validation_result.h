// What a validation is asked (VAL's -t and its numeric slack) and what it
// answers: the types the validator (validator.h) and its step-by-step
// executor (happening_executor.h) share, apart from both so that neither
// includes the other.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>

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
};

struct ValidationResult {
  bool valid = false;
  double makespan = 0.0;        // time of the last happening with an action
  std::optional<double> metric;  // the metric's value, when the problem has one
  double value = 0.0;           // VAL's "Final value"
  // The sum of action costs, (total-cost) after the last action happening,
  // when the domain declares it; the metric may weigh it with other terms.
  std::optional<double> total_cost;
  std::optional<Violation> violation;
  std::size_t happenings = 0;
  // PDDL 3: violated instances per preference name, as (is-violated name)
  // reads them in the metric.
  std::map<std::string, double> preference_violations;
};

}  // namespace alplan
