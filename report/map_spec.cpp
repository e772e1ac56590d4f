// The home's map with the robots' routes (chart_specs.h).
#include <algorithm>
#include <cmath>
#include <map>

#include "report/chart_specs.h"

namespace alplan::report {
namespace {

using nlohmann::json;

struct Extent {
  double min_x = 0, max_x = 0, min_y = 0, max_y = 0;
  double span() const { return std::max({max_x - min_x, max_y - min_y, 1.0}); }
};

Extent extent(const Home& home) {
  Extent e{home.rooms[0].x, home.rooms[0].x, home.rooms[0].y, home.rooms[0].y};
  for (const Room& r : home.rooms) {
    e.min_x = std::min(e.min_x, r.x);
    e.max_x = std::max(e.max_x, r.x);
    e.min_y = std::min(e.min_y, r.y);
    e.max_y = std::max(e.max_y, r.y);
  }
  return e;
}

const Room* find_room(const Home& home, const std::string& name) {
  const auto it = std::find_if(home.rooms.begin(), home.rooms.end(), [&](const Room& r) { return r.name == name; });
  return it == home.rooms.end() ? nullptr : &*it;
}

std::string names_in(const std::vector<Placement>& list, const std::string& room) {
  std::string out;
  for (const Placement& p : list) {
    if (p.room == room) out += (out.empty() ? "" : ", ") + p.name;
  }
  return out.empty() ? "-" : out;
}

json connection_layer(const Home& home) {
  json rows = json::array();
  for (const auto& [a, b] : home.connections) {
    const Room* from = find_room(home, a);
    const Room* to = find_room(home, b);
    if (from && to) rows.push_back({{"x", from->x}, {"y", from->y}, {"x2", to->x}, {"y2", to->y}});
  }
  return {{"data", {{"values", rows}}},
          {"mark", {{"type", "rule"}, {"color", "#d9d9d9"}, {"strokeWidth", 10}, {"strokeCap", "round"}}},
          {"encoding",
           {{"x", {{"field", "x"}, {"type", "quantitative"}}},
            {"y", {{"field", "y"}, {"type", "quantitative"}}},
            {"x2", {{"field", "x2"}}},
            {"y2", {{"field", "y2"}}}}}};
}

// Each robot's route as a line through the rooms it moved to, nudged apart
// a little per robot so two robots on one corridor stay visible.
json route_rows(const EventLog& log, const Extent& e) {
  json rows = json::array();
  const auto routes = robot_routes(log);
  const double nudge = 0.015 * e.span();
  int index = 0;
  for (const auto& [robot, moves] : routes) {
    const double d = nudge * (index++ - (static_cast<double>(routes.size()) - 1) / 2);
    int order = 0;
    auto add = [&](const std::string& room, double time, const std::string& step) {
      const Room* r = find_room(*log.home, room);
      if (!r) return;
      rows.push_back({{"robot", robot}, {"order", order++}, {"x", r->x + d}, {"y", r->y + d},
                      {"room", room}, {"time", time}, {"step", step}});
    };
    std::string at;
    for (const Move& m : moves) {
      // A move from elsewhere than the last one ended (a missed log line,
      // the robot carried) starts the line again from where it left.
      if (m.from != at) add(m.from, m.time, at.empty() ? "start" : "(from " + m.from + ")");
      add(m.to, m.time, m.from + " -> " + m.to);
      at = m.to;
    }
  }
  return rows;
}

json route_layers(const EventLog& log, const Extent& e) {
  const json rows = route_rows(log, e);
  const json tooltip = json::array({{{"field", "robot"}},
                                    {{"field", "step"}, {"title", "move"}},
                                    {{"field", "time"}, {"title", "started at"}},
                                    {{"field", "order"}, {"title", "move number"}}});
  const json colour = {{"field", "robot"}, {"type", "nominal"}, {"title", "route of"}};
  json line = {{"data", {{"values", rows}}},
               {"mark", {{"type", "line"}, {"strokeWidth", 3}, {"opacity", 0.85}, {"point", {{"size", 50}}}}},
               {"encoding",
                {{"x", {{"field", "x"}, {"type", "quantitative"}}},
                 {"y", {{"field", "y"}, {"type", "quantitative"}}},
                 {"order", {{"field", "order"}, {"type", "quantitative"}}},
                 {"color", colour},
                 {"tooltip", tooltip}}}};
  // The robot's name where its route starts: the line alone does not say
  // which end it left from.
  json start = {{"data", {{"values", rows}}},
                {"transform", json::array({{{"filter", "datum.order === 0"}},
                                           {{"calculate", "datum.robot + ' starts here'"}, {"as", "label"}}})},
                {"mark", {{"type", "text"}, {"align", "left"}, {"dx", 16}, {"dy", 4}, {"fontSize", 10},
                          {"fontWeight", "bold"}}},
                {"encoding",
                 {{"x", {{"field", "x"}, {"type", "quantitative"}}},
                  {"y", {{"field", "y"}, {"type", "quantitative"}}},
                  {"text", {{"field", "label"}}},
                  {"color", colour}}}};
  return json::array({line, start});
}

json room_rows(const Home& home) {
  json rows = json::array();
  for (const Room& r : home.rooms) {
    rows.push_back({{"room", r.name},
                    {"x", r.x},
                    {"y", r.y},
                    {"seniors", names_in(home.seniors, r.name)},
                    {"robots", names_in(home.robots, r.name)},
                    {"objects", names_in(home.objects, r.name)}});
  }
  return rows;
}

json room_layers(const Home& home) {
  const json rows = room_rows(home);
  const json position = {{"x", {{"field", "x"}, {"type", "quantitative"}}},
                         {"y", {{"field", "y"}, {"type", "quantitative"}}}};
  json squares = {{"data", {{"values", rows}}},
                  {"mark", {{"type", "square"}, {"size", 500}, {"fill", "white"}, {"stroke", "#555"}, {"filled", true}}},
                  {"encoding", position}};
  squares["encoding"]["tooltip"] = json::array({{{"field", "room"}},
                                                {{"field", "seniors"}, {"title", "seniors at start"}},
                                                {{"field", "robots"}, {"title", "robots at start"}},
                                                {{"field", "objects"}}});
  json labels = {{"data", {{"values", rows}}},
                 {"mark", {{"type", "text"}, {"dy", -20}, {"fontSize", 11}, {"fontWeight", "bold"}}},
                 {"encoding", position}};
  labels["encoding"]["text"] = {{"field", "room"}};
  json people = {{"data", {{"values", rows}}},
                 {"transform", json::array({{{"filter", "datum.seniors !== '-'"}}})},
                 {"mark", {{"type", "text"}, {"dy", 22}, {"fontSize", 10}, {"fontStyle", "italic"}, {"color", "#8c564b"}}},
                 {"encoding", position}};
  people["encoding"]["text"] = {{"field", "seniors"}};
  return json::array({squares, labels, people});
}

}  // namespace

json map_spec(const EventLog& log) {
  if (!log.home || log.home->rooms.empty()) return nullptr;
  const Home& home = *log.home;
  const Extent e = extent(home);
  // Equal units on both axes, so the map is not stretched; a margin of a
  // tenth keeps the labels of edge rooms inside.
  const double margin = 0.1 * e.span();
  const double width = 900;
  const double dx = e.max_x - e.min_x + 2 * margin;
  const double dy = e.max_y - e.min_y + 2 * margin;
  const double height = std::clamp(width * dy / dx, 200.0, 900.0);
  json layers = json::array({connection_layer(home)});
  if (!robot_routes(log).empty()) {
    for (json& l : route_layers(log, e)) layers.push_back(std::move(l));
  }
  for (json& l : room_layers(home)) layers.push_back(std::move(l));
  const json x_scale = {{"domain", {e.min_x - margin, e.max_x + margin}}, {"nice", false}, {"zero", false}};
  const json y_scale = {{"domain", {e.min_y - margin, e.max_y + margin}}, {"nice", false}, {"zero", false}};
  layers[0]["encoding"]["x"]["scale"] = x_scale;
  layers[0]["encoding"]["y"]["scale"] = y_scale;
  layers[0]["encoding"]["x"]["title"] = "x";
  layers[0]["encoding"]["y"]["title"] = "y";
  return {{"$schema", kVegaLiteSchema},
          {"width", width},
          {"height", std::round(height)},
          {"layer", layers},
          {"config", {{"legend", {{"orient", "right"}}}}}};
}

}  // namespace alplan::report
