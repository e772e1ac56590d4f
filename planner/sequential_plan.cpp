#include "planner/sequential_plan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "planner/validator.h"

namespace alplan {

bool reads_no_time(const GroundTask& task) {
  if (!task.timed_literals.empty()) return false;
  return std::none_of(task.actions.begin(), task.actions.end(), [](const GroundAction& a) { return a.durative; });
}

namespace {

std::string cost_text(double cost) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", cost);
  return buffer;
}

}  // namespace

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
  const bool unit = !check.total_cost.has_value();
  const double cost = unit ? static_cast<double>(sequential.steps.size()) : *check.total_cost;
  return text + "; cost = " + cost_text(cost) + (unit ? " (unit cost)" : " (general cost)") + "\n";
}

}  // namespace alplan
