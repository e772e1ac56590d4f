#include "cli/plan_output.h"

#include <sstream>

#include "planner/plan.h"
#include "planner/sequential_plan.h"

namespace alplan::cli {

const PrintedPlan& PlanPrinter::printed(const FoundPlan& plan) {
  const auto known = by_text_.find(plan.text);
  if (known != by_text_.end()) return known->second;
  PrintedPlan p{plan.text, false};
  if (task_) {
    if (std::optional<std::string> sequential = sequential_plan_text(*task_, plan)) p = {*sequential, true};
  }
  return by_text_.emplace(plan.text, std::move(p)).first->second;
}

// Times are the printed plan's (three decimals on the 0.001 grid), as
// numbers; `cost` is the sum of action costs where the domain has them (the
// metric may weigh it with the makespan), VAL's value otherwise; `metric`
// and `value` are the metric's and VAL's values.
nlohmann::json plan_json(const FoundPlan& p, const PrintedPlan& printed, std::size_t index) {
  nlohmann::json steps = nlohmann::json::array();
  for (const PlanStep& s : p.plan.steps) {
    nlohmann::json step = {
        {"time", printed.sequential ? nlohmann::json() : nlohmann::json(rounded_plan_time(*s.time))},
        {"action", s.action},
        {"args", s.args}};
    if (s.duration) step["duration"] = rounded_plan_time(*s.duration);
    steps.push_back(step);
  }
  const ValidationResult& v = p.validation;
  return {{"index", index},
          {"format", printed.sequential ? "sequential" : "temporal"},
          {"steps", steps},
          {"makespan", rounded_plan_time(v.makespan)},
          {"metric", v.metric ? nlohmann::json(*v.metric) : nlohmann::json()},
          {"value", v.value},
          {"cost", v.total_cost.value_or(v.value)},
          {"total_cost", v.total_cost ? nlohmann::json(*v.total_cost) : nlohmann::json()},
          {"preference_violations", v.preference_violations},
          {"found_after_seconds", p.seconds},
          {"search", p.engine},
          {"text", printed.text}};
}

nlohmann::json outcome_json(const std::string& status, const std::string& message, const std::string& diagnostics) {
  nlohmann::json lines = nlohmann::json::array();
  std::istringstream in(diagnostics);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(line);
  }
  return {{"schema_version", kPlanJsonSchemaVersion},
          {"status", status},
          {"message", message},
          {"limit", nullptr},
          {"diagnostics", lines},
          {"best", nullptr},
          {"best_index", nullptr},
          {"plans", nlohmann::json::array()},
          {"statistics",
           {{"expanded", 0}, {"evaluated", 0}, {"generated", 0}, {"duplicates", 0}, {"unschedulable", 0},
            {"dead_ends", 0}}},
          {"seconds", {{"grounding", nullptr}, {"setup", nullptr}, {"search", nullptr}, {"validation", nullptr}}}};
}

}  // namespace alplan::cli
