// The home's event log: JSON Lines, one object per event, each with `type`
// (stress, emotion, goal, plan, action_start, action_end, observation,
// failure, repair, explanation, comforted, window_missed), the simulated
// `time`, the `senior` and `robot` concerned when there are, and the
// payload's fields beside them. The first line is the observation of the
// home itself (`what: "home"`): its map, seniors, robots and objects, and
// the settings the run was made with, so that `alplan replay` can run it
// again and `alplan report` can draw it.
#pragma once

#include <functional>
#include <istream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace alplan::home {

struct LogEvent {
  std::string type;
  double time = 0.0;
  std::string senior;  // empty: none concerned
  std::string robot;
  nlohmann::json payload = nlohmann::json::object();
};

// The line's object: type, time, senior and robot (when set), then the
// payload's fields.
nlohmann::json to_json(const LogEvent& event);

// Keeps every event and, when given a stream, writes each as a line at once
// and flushes it, so that a run that dies leaves its log up to the end.
class EventLog {
 public:
  using Echo = std::function<void(const LogEvent&)>;
  // `echo`: told of every event as it is written (a terminal's narration).
  explicit EventLog(std::ostream* out = nullptr, Echo echo = {}) : out_(out), echo_(std::move(echo)) {}
  void write(LogEvent event);
  const std::vector<LogEvent>& events() const { return events_; }

 private:
  std::ostream* out_;
  Echo echo_;
  std::vector<LogEvent> events_;
};

class LogError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LogReading {
  std::vector<nlohmann::json> events;  // the usable lines, in order
  std::vector<std::size_t> lines;      // each one's line number
  std::vector<std::string> warnings;   // "run.jsonl:17: not JSON: ..."
};

// Reads what it can: a line that is not a JSON object with a string `type`
// and a numeric `time` is a warning naming its line, and the rest is still
// read. Throws LogError when the file cannot be opened or no line is usable.
LogReading read_event_log(const std::string& path);
LogReading read_event_log(std::istream& in, const std::string& source);

// The events of a replay against those of the log, field by field, leaving
// out wall-clock measurements (planning_seconds, seconds): the first that
// differs, in words naming the log's line, or nothing when they agree.
std::optional<std::string> first_difference(const LogReading& logged, const std::vector<LogEvent>& replayed);

}  // namespace alplan::home
