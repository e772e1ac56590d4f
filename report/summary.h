// The numbers a reader of a run wants first: who had goals, who was
// comforted and in time, which windows were missed, how failures were
// repaired.
#pragma once

#include <string>
#include <vector>

#include "report/event_log.h"

namespace alplan::report {

struct SeniorSummary {
  std::string senior;
  int goals = 0;
  int comforted = 0;
  int within_window = 0;
  int windows_missed = 0;
  // Comforted after the window closed: how late, summed and at worst.
  int late = 0;
  double lateness_total = 0;
  double lateness_max = 0;
};

// How busy a robot was: the union of its actions' spans (action_start to
// action_end), in all and per hour of the run.
struct RobotUtilisation {
  std::string robot;
  double busy_seconds = 0;
  std::vector<double> busy_share_per_hour;  // hour h: [3600 h, 3600 (h + 1)), up to the last event
};

struct StrategySummary {
  std::string strategy;
  int attempts = 0;
  int repaired = 0;
  double seconds = 0;  // planning time of its attempts, summed
};

// A robot's battery (logs of `alplan home --battery`): its lowest level,
// from the `battery` events and the levels `action_end` events carry.
struct BatterySummary {
  std::string robot;
  double lowest = 0;
  double reserve = 0;
  bool below_reserve = false;
};

struct RunSummary {
  double end_time = 0;  // the last event's time
  int plans = 0;
  int seniors_with_goals = 0;
  int goals = 0;
  int comforted = 0;
  int within_window = 0;
  int windows_missed = 0;
  int failures = 0;
  int foreseen_failures = 0;
  int explanations = 0;
  std::vector<SeniorSummary> seniors;      // those the log mentions, by name
  std::vector<StrategySummary> repairs;    // by strategy name
  std::vector<BatterySummary> batteries;   // by robot; empty without batteries
  std::vector<RobotUtilisation> robots;    // by robot, those the log names
};

RunSummary summarize(const EventLog& log);

}  // namespace alplan::report
