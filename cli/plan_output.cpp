#include "cli/plan_output.h"

#include <cstdio>
#include <sstream>

#include "planner/plan.h"
#include "planner/sequential_plan.h"

namespace alplan::cli {

std::string printed_plan_text(const GroundTask* task, const FoundPlan& plan) {
  if (task) {
    if (std::optional<std::string> sequential = sequential_plan_text(*task, plan)) return *sequential;
  }
  return plan.text;
}

// Times are the printed plan's (three decimals on the 0.001 grid), as
// numbers; `cost` is the sum of action costs where the domain has them (the
// metric may weigh it with the makespan), VAL's value otherwise; `metric`
// and `value` are the metric's and VAL's values.
nlohmann::json plan_json(const GroundTask* task, const FoundPlan& p, std::size_t index) {
  const std::string text = printed_plan_text(task, p);
  const bool sequential = text != p.text;
  nlohmann::json steps = nlohmann::json::array();
  for (const PlanStep& s : p.plan.steps) {
    nlohmann::json step = {{"time", sequential ? nlohmann::json() : nlohmann::json(rounded_plan_time(*s.time))},
                           {"action", s.action},
                           {"args", s.args}};
    if (s.duration) step["duration"] = rounded_plan_time(*s.duration);
    steps.push_back(step);
  }
  const ValidationResult& v = p.validation;
  return {{"index", index},
          {"format", sequential ? "sequential" : "temporal"},
          {"steps", steps},
          {"makespan", rounded_plan_time(v.makespan)},
          {"metric", v.metric ? nlohmann::json(*v.metric) : nlohmann::json()},
          {"value", v.value},
          {"cost", v.total_cost.value_or(v.value)},
          {"total_cost", v.total_cost ? nlohmann::json(*v.total_cost) : nlohmann::json()},
          {"preference_violations", v.preference_violations},
          {"found_after_seconds", p.seconds},
          {"search", p.engine},
          {"text", text}};
}

nlohmann::json outcome_json(const std::string& status, const std::string& message) {
  return {{"schema_version", kPlanJsonSchemaVersion},
          {"status", status},
          {"message", message},
          {"limit", nullptr},
          {"diagnostics", nlohmann::json::array()},
          {"best", nullptr},
          {"best_index", nullptr},
          {"plans", nlohmann::json::array()},
          {"statistics",
           {{"expanded", 0}, {"evaluated", 0}, {"generated", 0}, {"duplicates", 0}, {"unschedulable", 0},
            {"dead_ends", 0}}},
          {"seconds", {{"grounding", nullptr}, {"setup", nullptr}, {"search", nullptr}, {"validation", nullptr}}}};
}

nlohmann::json input_error_json(const std::string& message, const std::string& diagnostics) {
  nlohmann::json j = outcome_json("input_error", message);
  std::istringstream lines(diagnostics);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty()) j["diagnostics"].push_back(line);
  }
  return j;
}

std::string seconds_text(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", seconds);
  return buffer;
}

}  // namespace alplan::cli
