#include "report/event_log.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>

namespace alplan::report {
namespace {

using nlohmann::json;

// Each known type, with the field it cannot be drawn without (besides type
// and time); empty when none is needed.
struct TypeRule {
  const char* type;
  const char* needs;
};
constexpr TypeRule kTypes[] = {
    {"stress", "senior"},          {"emotion", "senior"},      {"goal", "senior"},
    {"plan", "plan_id"},           {"action_start", "action"}, {"action_end", "action"},
    {"observation", ""},           {"failure", ""},            {"repair", ""},
    {"explanation", ""},           {"comforted", "senior"},    {"window_missed", "senior"},
    {"battery", "robot"},          {"robot_down", "robot"},    {"robot_up", "robot"},
    {"window_passed", "senior"},   {"goal_confirmed", "senior"}, {"goal_superseded", "senior"},
};

const TypeRule* rule_for(const std::string& type) {
  for (const TypeRule& r : kTypes) {
    if (type == r.type) return &r;
  }
  return nullptr;
}

// nlohmann's messages start with "[json.exception.parse_error.101] ", which
// tells a reader of the log nothing, and say "at line 1", the line within
// the one-line text parsed, which reads as the log's first line.
std::string parse_message(const json::parse_error& e) {
  std::string m = e.what();
  const auto bracket = m.find("] ");
  if (bracket != std::string::npos) m = m.substr(bracket + 2);
  const auto line_one = m.find("at line 1, column");
  if (line_one != std::string::npos) m.replace(line_one, 17, "at column");
  return m;
}

std::vector<Placement> placements(const json& list, bool with_type) {
  std::vector<Placement> out;
  if (!list.is_array()) return out;
  for (const json& p : list) {
    if (text_field(p, "name").empty()) continue;
    out.push_back({text_field(p, "name"), text_field(p, "room"), with_type ? text_field(p, "type") : ""});
  }
  return out;
}

Home read_home(const json& h, const std::string& where, std::ostream& warnings) {
  Home home;
  home.name = text_field(h, "name");
  if (h.contains("rooms") && h["rooms"].is_array()) {
    for (const json& r : h["rooms"]) {
      const auto x = optional_number(r, "x");
      const auto y = optional_number(r, "y");
      if (text_field(r, "name").empty() || !x || !y) {
        warnings << where << ": warning: a room without a name or coordinates, left off the map: " << r.dump() << "\n";
        continue;
      }
      home.rooms.push_back({text_field(r, "name"), *x, *y});
    }
  }
  if (h.contains("connections") && h["connections"].is_array()) {
    for (const json& c : h["connections"]) {
      if (c.is_array() && c.size() == 2 && c[0].is_string() && c[1].is_string()) {
        home.connections.emplace_back(c[0].get<std::string>(), c[1].get<std::string>());
      }
    }
  }
  home.seniors = placements(h.value("seniors", json()), false);
  home.robots = placements(h.value("robots", json()), false);
  home.objects = placements(h.value("objects", json()), true);
  return home;
}

// Why the object cannot be used as an event; empty when it can.
std::string unusable_because(const json& j, const TypeRule* rule) {
  if (!j.is_object()) return "not a JSON object";
  if (!j.contains("type") || !j["type"].is_string()) return "no \"type\"";
  if (!rule) return "unknown event type '" + j["type"].get<std::string>() + "'";
  if (!j.contains("time") || !j["time"].is_number() || !std::isfinite(j["time"].get<double>())) {
    return "no numeric \"time\"";
  }
  const std::string needs = rule->needs;
  const std::string event = "a \"" + std::string(rule->type) + "\" event without ";
  if (needs == "plan_id" && !optional_int(j, "plan_id")) return event + "an integer \"plan_id\"";
  if ((needs == "senior" || needs == "action") && text_field(j, rule->needs).empty()) {
    return event + "\"" + needs + "\"";
  }
  return "";
}

}  // namespace

std::string text_field(const json& j, const char* key, const std::string& fallback) {
  if (!j.is_object()) return fallback;
  const auto it = j.find(key);
  return it != j.end() && it->is_string() ? it->get<std::string>() : fallback;
}

std::optional<double> optional_number(const json& j, const char* key) {
  if (!j.is_object()) return std::nullopt;
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number()) return std::nullopt;
  const double v = it->get<double>();
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

double number_field(const json& j, const char* key, double fallback) {
  return optional_number(j, key).value_or(fallback);
}

std::optional<int> optional_int(const json& j, const char* key) {
  if (!j.is_object()) return std::nullopt;
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number_integer()) return std::nullopt;
  return static_cast<int>(it->get<long long>());
}

bool bool_field(const json& j, const char* key, bool fallback) {
  if (!j.is_object()) return fallback;
  const auto it = j.find(key);
  return it != j.end() && it->is_boolean() ? it->get<bool>() : fallback;
}

ReadResult read_event_log(std::istream& in, const std::string& name, std::ostream& warnings) {
  EventLog log;
  std::string line;
  int number = 0;
  int usable = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string where = name + ":" + std::to_string(number);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    json j;
    try {
      j = json::parse(line);
    } catch (const json::parse_error& e) {
      warnings << where << ": warning: not JSON: " << parse_message(e) << "\n";
      continue;
    }
    const std::string type = text_field(j, "type");
    const std::string why = unusable_because(j, rule_for(type));
    if (!why.empty()) {
      warnings << where << ": warning: " << why << "; line skipped\n";
      continue;
    }
    ++usable;
    if (type == "observation" && text_field(j, "what") == "home" && j.contains("home") && j["home"].is_object()) {
      if (log.home) warnings << where << ": warning: a second home observation; the first is kept\n";
      if (!log.home) log.home = read_home(j["home"], where, warnings);
      if (log.settings.is_null() && j.contains("settings")) log.settings = j["settings"];
      continue;
    }
    log.events.push_back({number, type, j["time"].get<double>(), text_field(j, "senior"), text_field(j, "robot"), j});
  }
  if (usable == 0) return {std::nullopt, name + ": error: no usable event in the log (expected JSON Lines, one event a line)"};
  return {std::move(log), ""};
}

ReadResult read_event_log_file(const std::string& path, std::ostream& warnings) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return {std::nullopt, path + ": error: a directory, not a log file"};
  std::ifstream in(path);
  if (!in) return {std::nullopt, path + ": error: cannot open the file"};
  return read_event_log(in, path, warnings);
}

}  // namespace alplan::report
