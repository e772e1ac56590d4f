// The seniors' stress and emotion timelines (chart_specs.h).
#include <set>

#include "report/chart_specs.h"

namespace alplan::report {
namespace {

using nlohmann::json;

constexpr const char* kStress = "stress score";
constexpr const char* kWindow = "goal window";
constexpr const char* kInTime = "comforted in time";
constexpr const char* kLate = "comforted late";
constexpr const char* kMissed = "window missed";

json row(const Event& e, const char* kind, const std::string& what) {
  return {{"senior", e.senior}, {"kind", kind}, {"what", what}, {"time", e.time}};
}

// One row per drawn thing; every layer picks its kind, as a facet has one
// data source.
json timeline_rows(const EventLog& log) {
  json rows = json::array();
  for (const Event& e : log.events) {
    const json& f = e.fields;
    if (e.type == "stress") {
      json r = row(e, "stress", kStress);
      r["score"] = number_field(f, "score");
      r["stressed"] = bool_field(f, "stressed") ? "yes" : "no";
      rows.push_back(r);
    } else if (e.type == "emotion") {
      json r = row(e, "emotion", "emotion: " + text_field(f, "emotion", "unknown"));
      r["score"] = number_field(f, "score");
      r["look"] = optional_int(f, "look") ? json(*optional_int(f, "look")) : json("-");
      rows.push_back(r);
    } else if (e.type == "goal") {
      json r = row(e, "goal", kWindow);
      r["time_end"] = number_field(f, "window_end", e.time);
      for (const char* k : {"goal", "emotion", "motivation", "decided_by"}) r[k] = text_field(f, k, "-");
      rows.push_back(r);
    } else if (e.type == "comforted" || e.type == "window_missed") {
      const bool missed = e.type == "window_missed";
      json r = row(e, missed ? "missed" : "comforted",
                   missed ? kMissed : bool_field(f, "within_window") ? kInTime : kLate);
      r["goal"] = text_field(f, "goal", "-");
      r["window_end"] = optional_number(f, "window_end") ? json(*optional_number(f, "window_end")) : json("-");
      rows.push_back(r);
    }
  }
  return rows;
}

json colour_scale(const json& rows) {
  json domain = {kStress, kWindow, kInTime, kLate, kMissed};
  json range = {"#333333", "#9ecae9", "#2ca02c", "#ff7f0e", "#d62728"};
  std::set<std::string> emotions;
  for (const json& r : rows) {
    if (r["kind"] == "emotion") emotions.insert(r["what"].get<std::string>());
  }
  // Tableau's colours but green, orange and red: they mean comforted, late
  // and missed here.
  static constexpr const char* kEmotionColours[] = {"#4c78a8", "#b279a2", "#72b7b2", "#eeca3b",
                                                    "#9d755d", "#ff9da6", "#bab0ac", "#1f3b73"};
  std::size_t i = 0;
  for (const std::string& e : emotions) {
    domain.push_back(e);
    range.push_back(kEmotionColours[i++ % (sizeof kEmotionColours / sizeof kEmotionColours[0])]);
  }
  return {{"domain", domain}, {"range", range}};
}

json layer(const char* kind, json mark, json encoding) {
  encoding["x"] = {{"field", "time"}, {"type", "quantitative"}, {"title", "simulated time (s)"}};
  encoding["color"] = {{"field", "what"}, {"type", "nominal"}, {"title", nullptr}};
  return {{"transform", json::array({{{"filter", {{"field", "kind"}, {"equal", kind}}}}})},
          {"mark", std::move(mark)},
          {"encoding", std::move(encoding)}};
}

json tooltip(std::initializer_list<const char*> fields) {
  json t = json::array({{{"field", "senior"}}, {{"field", "what"}}, {{"field", "time"}}});
  for (const char* f : fields) t.push_back({{"field", f}});
  return t;
}

json timeline_layers() {
  const json score = {{"field", "score"}, {"type", "quantitative"}, {"title", "score"}};
  json window = layer("goal", {{"type", "rect"}, {"opacity", 0.35}},
                      {{"x2", {{"field", "time_end"}}},
                       {"tooltip", tooltip({"time_end", "goal", "emotion", "motivation", "decided_by"})}});
  json stress_line = layer("stress", {{"type", "line"}, {"strokeWidth", 1.5}}, {{"y", score}});
  // Big dots where the senior was stressed, small ones where not.
  json stress_dots = layer("stress", {{"type", "point"}, {"filled", true}},
                           {{"y", score},
                            {"size", {{"condition", {{"test", "datum.stressed === 'yes'"}, {"value", 70}}}, {"value", 12}}},
                            {"tooltip", tooltip({"score", "stressed"})}});
  json emotions = layer("emotion", {{"type", "point"}, {"shape", "diamond"}, {"filled", true}, {"size", 90}},
                        {{"y", score}, {"tooltip", tooltip({"score", "look"})}});
  json comforted = layer("comforted", {{"type", "rule"}, {"strokeWidth", 3}},
                         {{"tooltip", tooltip({"goal", "window_end"})}});
  json missed = layer("missed", {{"type", "rule"}, {"strokeWidth", 3}, {"strokeDash", {4, 3}}},
                      {{"tooltip", tooltip({"goal", "window_end"})}});
  return json::array({window, stress_line, stress_dots, emotions, comforted, missed});
}

}  // namespace

json timeline_spec(const EventLog& log) {
  json rows = timeline_rows(log);
  if (rows.empty()) return nullptr;
  json layers = timeline_layers();
  layers[0]["encoding"]["color"]["scale"] = colour_scale(rows);
  layers[0]["encoding"]["x"]["scale"] = {{"domain", {0, run_end(log)}}, {"nice", false}};
  return {{"$schema", kVegaLiteSchema},
          {"data", {{"values", rows}}},
          {"facet",
           {{"row",
             {{"field", "senior"},
              {"type", "nominal"},
              {"title", nullptr},
              {"header", {{"labelAngle", 0}, {"labelAlign", "left"}, {"labelFontWeight", "bold"}}}}}}},
          {"spec", {{"width", 1000}, {"height", 110}, {"layer", layers}}},
          {"config", {{"legend", {{"orient", "bottom"}, {"columns", 5}, {"symbolOpacity", 1}}}}}};
}

}  // namespace alplan::report
