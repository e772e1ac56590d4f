// The Gantt chart of a run's plans (chart_specs.h).
#include <algorithm>
#include <set>

#include "report/chart_specs.h"

namespace alplan::report {
namespace {

using nlohmann::json;

constexpr const char* kNeverRan = "never ran (superseded)";
constexpr const char* kNeverRanColour = "#c7c7c7";

std::string plan_label(const PlanRecord& p) {
  return "plan " + std::to_string(p.plan_id) + (p.reason.empty() ? "" : " (" + p.reason + ")");
}

std::string plan_label(const PlanHistory& h, int plan_id) {
  for (const PlanRecord& p : h.plans) {
    if (p.plan_id == plan_id) return plan_label(p);
  }
  return "plan " + std::to_string(plan_id);
}

json step_rows(const PlanHistory& h) {
  json rows = json::array();
  for (const PlanStep& s : h.steps) {
    const std::string plan = plan_label(h, s.plan_id);
    json row = {{"robot", s.robot.empty() ? "(no robot)" : s.robot},
                {"plan", plan},
                {"colour", s.status == StepStatus::NeverRan ? kNeverRan : plan},
                {"action", s.action},
                {"status", to_string(s.status)},
                {"start", s.start},
                {"end", s.start + s.duration},
                {"duration", s.duration}};
    row["started_at"] = s.started_at ? json(*s.started_at) : json("-");
    row["ended_at"] = s.ended_at ? json(*s.ended_at) : json("-");
    rows.push_back(row);
  }
  return rows;
}

// Colour by plan in the order plans were made, grey last for the steps that
// never ran.
json colour_scale(const PlanHistory& h) {
  json domain = json::array();
  json range = json::array();
  for (std::size_t i = 0; i < h.plans.size(); ++i) {
    domain.push_back(plan_label(h.plans[i]));
    range.push_back(category_colour(i));
  }
  domain.push_back(kNeverRan);
  range.push_back(kNeverRanColour);
  return {{"domain", domain}, {"range", range}};
}

json bar_layer(const PlanHistory& h) {
  return {
      {"data", {{"values", step_rows(h)}}},
      {"mark", {{"type", "bar"}, {"cornerRadius", 2}, {"stroke", "white"}, {"strokeWidth", 0.5}}},
      {"encoding",
       {{"x", {{"field", "start"}, {"type", "quantitative"}, {"title", "simulated time (s)"}}},
        {"x2", {{"field", "end"}}},
        {"y", {{"field", "robot"}, {"type", "nominal"}, {"title", nullptr}}},
        {"yOffset", {{"field", "plan"}, {"type", "nominal"}}},
        {"color", {{"field", "colour"}, {"type", "nominal"}, {"title", "plan"}, {"scale", colour_scale(h)}}},
        {"tooltip", json::array({{{"field", "action"}},
                                 {{"field", "plan"}},
                                 {{"field", "status"}},
                                 {{"field", "start"}, {"title", "planned start"}},
                                 {{"field", "duration"}},
                                 {{"field", "started_at"}, {"title", "started at"}},
                                 {{"field", "ended_at"}, {"title", "ended at"}}})}}}};
}

// Instantaneous steps (a device's answer) take no time: a bar would have no
// width, so each is a point in its row, coloured by its plan.
json instant_layer(const PlanHistory& h) {
  json rows = json::array();
  for (const json& row : step_rows(h)) {
    if (row.at("duration").get<double>() == 0.0) rows.push_back(row);
  }
  if (rows.empty()) return nullptr;
  return {{"data", {{"values", rows}}},
          {"mark", {{"type", "point"}, {"shape", "triangle-right"}, {"filled", true}, {"size", 120}}},
          {"encoding",
           {{"x", {{"field", "start"}, {"type", "quantitative"}}},
            {"y", {{"field", "robot"}, {"type", "nominal"}}},
            {"color", {{"field", "colour"}, {"type", "nominal"}, {"scale", colour_scale(h)}}},
            {"tooltip", json::array({{{"field", "action"}}, {{"field", "plan"}}, {{"field", "status"}},
                                     {{"field", "start"}, {"title", "planned at"}},
                                     {{"field", "started_at"}, {"title", "done at"}}})}}}};
}

json failure_layers(const EventLog& log, double tick_size) {
  json rows = json::array();
  for (const Event& e : log.events) {
    if (e.type != "failure") continue;
    rows.push_back({{"robot", e.robot.empty() ? "(no robot)" : e.robot},
                    {"time", e.time},
                    {"action", text_field(e.fields, "action", "-")},
                    {"condition", text_field(e.fields, "condition", "-")},
                    {"kind", text_field(e.fields, "kind", "-")},
                    {"foreseen", bool_field(e.fields, "foreseen") ? "yes" : "no"}});
  }
  if (rows.empty()) return json::array();
  const json tooltip = json::array({{{"field", "time"}, {"title", "failure at"}},
                                    {{"field", "robot"}},
                                    {{"field", "action"}},
                                    {{"field", "condition"}},
                                    {{"field", "kind"}},
                                    {{"field", "foreseen"}}});
  const json position = {{"x", {{"field", "time"}, {"type", "quantitative"}}},
                         {"y", {{"field", "robot"}, {"type", "nominal"}}},
                         {"tooltip", tooltip}};
  // A tick, not a rule: a rule with a band position runs from the axis to
  // the time; a tick stands across the robot's row at the time.
  return json::array({{{"data", {{"values", rows}}},
                       {"mark", {{"type", "tick"}, {"color", "#d62728"}, {"thickness", 2.5}, {"size", tick_size}}},
                       {"encoding", position}},
                      {{"data", {{"values", rows}}},
                       {"mark", {{"type", "point"}, {"shape", "cross"}, {"color", "#d62728"}, {"filled", true},
                                 {"size", 140}}},
                       {"encoding", position}}});
}

json repair_layers(const EventLog& log) {
  json rows = json::array();
  for (const Event& e : log.events) {
    if (e.type != "repair") continue;
    const auto plan = optional_int(e.fields, "plan_id");
    rows.push_back({{"time", e.time},
                    {"strategy", text_field(e.fields, "strategy", "-")},
                    {"repaired", bool_field(e.fields, "repaired") ? "yes" : "no"},
                    {"seconds", number_field(e.fields, "seconds")},
                    {"plan", plan ? json(*plan) : json("-")},
                    {"how", text_field(e.fields, "how", "-")}});
  }
  if (rows.empty()) return json::array();
  const json tooltip = json::array({{{"field", "time"}, {"title", "repair at"}},
                                    {{"field", "strategy"}},
                                    {{"field", "repaired"}},
                                    {{"field", "seconds"}, {"title", "repair seconds"}},
                                    {{"field", "plan"}, {"title", "new plan"}},
                                    {{"field", "how"}}});
  // Green when the repair worked, orange when not: a rule across every row,
  // a repair belongs to the whole run.
  const json colour = {{"condition", {{"test", "datum.repaired === 'yes'"}, {"value", "#2ca02c"}}},
                       {"value", "#ff7f0e"}};
  return json::array(
      {{{"data", {{"values", rows}}},
        {"mark", {{"type", "rule"}, {"strokeDash", {6, 3}}, {"strokeWidth", 2}}},
        {"encoding", {{"x", {{"field", "time"}, {"type", "quantitative"}}}, {"color", colour}, {"tooltip", tooltip}}}},
       {{"data", {{"values", rows}}},
        {"mark", {{"type", "point"}, {"shape", "diamond"}, {"filled", true}, {"size", 120}}},
        {"encoding",
         {{"x", {{"field", "time"}, {"type", "quantitative"}}},
          {"y", {{"value", -8}}},
          {"color", colour},
          {"tooltip", tooltip}}}}});
}

}  // namespace

double run_end(const EventLog& log) {
  double end = 0;
  for (const Event& e : log.events) end = std::max({end, e.time, number_field(e.fields, "window_end")});
  return end;
}

const char* category_colour(std::size_t i) {
  static constexpr const char* kColours[] = {"#4c78a8", "#f58518", "#54a24b", "#b279a2", "#e45756",
                                             "#72b7b2", "#eeca3b", "#ff9da6", "#9d755d", "#bab0ac"};
  return kColours[i % (sizeof kColours / sizeof kColours[0])];
}

json gantt_spec(const EventLog& log, const PlanHistory& history) {
  if (history.steps.empty()) return nullptr;
  // From 0 to the end of the run or of the last step planned, as the
  // timelines below, so times line up down the page.
  double end = run_end(log);
  for (const PlanStep& s : history.steps) end = std::max(end, s.start + s.duration);
  std::set<std::string> robots;
  for (const PlanStep& s : history.steps) robots.insert(s.robot);
  // A sub-row per plan in each robot's row, so a repair plan's steps do not
  // hide the superseded steps they replaced.
  const std::size_t rows = robots.size() * std::max<std::size_t>(1, history.plans.size());
  const std::size_t height = std::clamp<std::size_t>(rows * 26, 120, 800);
  json layers = json::array({bar_layer(history)});
  layers[0]["encoding"]["x"]["scale"] = {{"domain", {0, end}}, {"nice", false}};
  const double row_height = static_cast<double>(height) / static_cast<double>(robots.size());
  if (json instant = instant_layer(history); !instant.is_null()) layers.push_back(std::move(instant));
  for (json& l : failure_layers(log, 0.9 * row_height)) layers.push_back(std::move(l));
  for (json& l : repair_layers(log)) layers.push_back(std::move(l));
  return {{"$schema", kVegaLiteSchema},
          {"width", 1000},
          {"height", height},
          {"layer", layers},
          {"config", {{"legend", {{"orient", "bottom"}, {"columns", 4}}}}}};
}

}  // namespace alplan::report
