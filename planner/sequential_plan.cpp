#include "planner/sequential_plan.h"

#include <algorithm>
#include <cmath>

#include "planner/validator.h"

namespace alplan {

bool reads_no_time(const GroundTask& task) {
  if (!task.timed_literals.empty()) return false;
  return std::none_of(task.actions.begin(), task.actions.end(), [](const GroundAction& a) { return a.durative; });
}

std::optional<std::string> sequential_plan_text(const GroundTask& task, const FoundPlan& found) {
  if (!reads_no_time(task) || !found.validation.valid || !task.lifted) return std::nullopt;
  Plan sequential = found.plan;
  for (PlanStep& step : sequential.steps) {
    step.time.reset();
    step.duration.reset();
  }
  std::string text;
  for (const PlanStep& step : sequential.steps) {
    text += "(" + step.action;
    for (const std::string& a : step.args) text += " " + a;
    text += ")\n";
  }
  PlanValidator validator(task.lifted);
  const ValidationResult check = validator.validate(read_plan(text, "sequential plan").plan);
  if (!check.valid || std::abs(check.value - found.validation.value) > 1e-9) return std::nullopt;
  // As `alplan plan --json` reports `cost`: the action costs' sum where the
  // domain has them, else the value (the step count without a metric).
  const char* kind = check.total_cost ? " (general cost)" : check.metric ? " (metric)" : " (unit cost)";
  return text + "; cost = " + format_value(check.total_cost.value_or(check.value)) + kind + "\n";
}

}  // namespace alplan
