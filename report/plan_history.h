// What became of each plan of a run: which steps ran, which were dropped
// when a later plan superseded theirs, and where each robot actually went.
// The Gantt chart and the map draw from this.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "report/event_log.h"

namespace alplan::report {

enum class StepStatus {
  Ran,          // an action_start of its plan and action was logged
  NeverRan,     // its plan was superseded before it started
  NotStarted,   // its plan is current at the end of the log, it has not started
};
const char* to_string(StepStatus s);

struct PlanStep {
  int plan_id = 0;
  std::string robot;
  std::string action;
  double start = 0;  // simulated seconds, on the log's clock
  double duration = 0;
  StepStatus status = StepStatus::NotStarted;
  std::optional<double> started_at;  // when its action_start was logged
  std::optional<double> ended_at;    // when its action_end was logged
};

struct PlanRecord {
  int plan_id = 0;
  double time = 0;  // when the plan was made
  std::string reason;
  std::optional<int> supersedes;
  std::optional<double> superseded_at;  // when a later plan replaced it
  double planning_seconds = 0;
};

struct PlanHistory {
  std::vector<PlanRecord> plans;  // in log order
  std::vector<PlanStep> steps;    // every plan's steps, in log order
};

// Step start times are read as simulated seconds on the log's clock; a plan
// whose steps start before the plan itself was made is taken to count from
// its own making (IPC plans start at 0) and is shifted to it.
PlanHistory plan_history(const EventLog& log);

// A move a robot started: `(move ROBOT FROM TO)`.
struct Move {
  double time = 0;
  std::string robot;
  std::string from;
  std::string to;
};

// The arguments of `(name arg...)`, name first; empty when it is not one.
std::vector<std::string> action_terms(const std::string& action);

// Each robot's moves actually started (action_start events), in time order.
std::map<std::string, std::vector<Move>> robot_routes(const EventLog& log);

}  // namespace alplan::report
