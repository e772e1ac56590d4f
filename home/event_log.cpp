#include "home/event_log.h"

#include <fstream>

namespace alplan::home {

nlohmann::json to_json(const LogEvent& event) {
  nlohmann::json line = nlohmann::json::object();
  line["type"] = event.type;
  line["time"] = event.time;
  if (!event.senior.empty()) line["senior"] = event.senior;
  if (!event.robot.empty()) line["robot"] = event.robot;
  for (const auto& [key, value] : event.payload.items()) line[key] = value;
  return line;
}

void EventLog::write(LogEvent event) {
  if (out_) {
    *out_ << to_json(event).dump() << '\n';
    out_->flush();
  }
  if (echo_) echo_(event);
  events_.push_back(std::move(event));
}

LogReading read_event_log(std::istream& in, const std::string& source) {
  LogReading reading;
  std::string text;
  for (std::size_t line = 1; std::getline(in, text); ++line) {
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = source + ":" + std::to_string(line) + ": ";
    nlohmann::json event;
    try {
      event = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
      reading.warnings.push_back(where + "not JSON (" + e.what() + ")");
      continue;
    }
    if (!event.is_object() || !event.contains("type") || !event["type"].is_string() || !event.contains("time") ||
        !event["time"].is_number()) {
      reading.warnings.push_back(where + "not an event (an object with a string \"type\" and a numeric \"time\")");
      continue;
    }
    reading.events.push_back(std::move(event));
    reading.lines.push_back(line);
  }
  if (reading.events.empty()) throw LogError(source + ": no event in the log");
  return reading;
}

namespace {

// Seconds of wall clock differ from run to run; everything else must not.
nlohmann::json without_clock(nlohmann::json event) {
  if (event.is_object()) {
    event.erase("planning_seconds");
    event.erase("seconds");
  }
  return event;
}

std::string shortened(const nlohmann::json& event) {
  std::string text = event.dump();
  return text.size() > 300 ? text.substr(0, 300) + "..." : text;
}

}  // namespace

std::optional<std::string> first_difference(const LogReading& logged, const std::vector<LogEvent>& replayed) {
  const std::size_t n = std::min(logged.events.size(), replayed.size());
  for (std::size_t i = 0; i < n; ++i) {
    const nlohmann::json a = without_clock(logged.events[i]), b = without_clock(to_json(replayed[i]));
    if (a != b) {
      return "line " + std::to_string(logged.lines[i]) + " differs:\n  logged:   " + shortened(a) +
             "\n  replayed: " + shortened(b);
    }
  }
  if (logged.events.size() > n) {
    return "the replay ends before line " + std::to_string(logged.lines[n]) + ": " + shortened(logged.events[n]);
  }
  if (replayed.size() > n) return "the replay goes on after the log's last line: " + shortened(to_json(replayed[n]));
  return std::nullopt;
}

LogReading read_event_log(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw LogError(path + ": cannot open the log");
  return read_event_log(in, path);
}

}  // namespace alplan::home
