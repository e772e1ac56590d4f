// A run's event log as `alplan home` writes it: JSON Lines, one event an
// object a line (report/README.md lists the types and their fields). Reading
// goes on past a bad line: a run cut short (a crash, a full disk) leaves a
// truncated last line, and the rest still tells most of the story.
#pragma once

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace alplan::report {

struct Room {
  std::string name;
  double x = 0;
  double y = 0;
};

// Where a senior, a robot or an object is when the run starts.
struct Placement {
  std::string name;
  std::string room;
  std::string type;  // objects only
};

// The home, from the log's first observation (`"what": "home"`).
struct Home {
  std::string name;
  std::vector<Room> rooms;  // only rooms with coordinates: the map needs them
  std::vector<std::pair<std::string, std::string>> connections;
  std::vector<Placement> seniors;
  std::vector<Placement> robots;
  std::vector<Placement> objects;
};

struct Event {
  int line = 0;  // 1-based line of the log, for messages
  std::string type;
  double time = 0;
  std::string senior;     // empty when the event concerns no senior
  std::string robot;      // empty when the event concerns no robot
  nlohmann::json fields;  // the whole object, payload and unknown fields included
};

struct EventLog {
  std::optional<Home> home;  // absent when the log lacks the home observation
  nlohmann::json settings;   // free-form; null when absent
  std::vector<Event> events;  // every usable line but the home one, in log order
};

struct ReadResult {
  std::optional<EventLog> log;
  std::string error;  // set when there is no log
};

// Reads a log named `name` in messages. Each unusable line is reported on
// `warnings` as "NAME:LINE: warning: ..." and skipped; a log without one
// usable line is an error.
ReadResult read_event_log(std::istream& in, const std::string& name, std::ostream& warnings);
ReadResult read_event_log_file(const std::string& path, std::ostream& warnings);

// Payload fields, forgiving: a missing, null or mistyped field gives the
// fallback, so an optional field left out never stops the report.
std::string text_field(const nlohmann::json& j, const char* key, const std::string& fallback = "");
double number_field(const nlohmann::json& j, const char* key, double fallback = 0);
std::optional<double> optional_number(const nlohmann::json& j, const char* key);
std::optional<int> optional_int(const nlohmann::json& j, const char* key);
bool bool_field(const nlohmann::json& j, const char* key, bool fallback = false);

}  // namespace alplan::report
