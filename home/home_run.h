// The running home (issue 16; the paper's Fig. 3 over a whole home): the
// seniors' stress and emotions come in over simulated time, goals are
// generated, the robots plan, act under the monitor and repair, and every
// step is written to the event log. Several seniors at once, and the
// robots as a fleet (issue 31): each goal has its window by urgency and goes
// to the robot with the least weighted lateness; several missions run at
// once, a busy robot merging a goal into its plan, committed to what is
// underway; a robot that breaks down hands its goals to the others; a window
// no plan can meet is served late (soft windows) or, with hard windows,
// dropped and its senior seen as stressed again.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "home/event_log.h"
#include "home/goal_source.h"
#include "home/home_map.h"
#include "home/home_settings.h"
#include "home/run_clock.h"

namespace alplan::home {

// A robot's battery over a run (`alplan home --battery`), from the
// simulated world's true values.
struct RobotBattery {
  double level = 0.0, lowest = 0.0, reserve = 0.0;
  bool below_reserve = false;  // lowest < reserve, beyond the validator's slack
};

struct HomeSummary {
  std::size_t goals = 0, comforted = 0, within_window = 0, windows_missed = 0;
  std::size_t failures = 0, plans = 0, merges = 0;
  std::map<std::string, std::size_t> repairs;  // by strategy, repaired
  std::size_t repairs_failed = 0;
  std::size_t objects_recognized = 0;  // by repairs, kept for the missions after
  // With score_meetable: goals one idle robot could have met alone, and of
  // those, the ones comforted within their windows.
  std::size_t meetable = 0, meetable_within_window = 0;
  // Goals whose windows closed before anyone comforted them (dropped), and
  // goals still in course when the run ended.
  std::size_t never_served = 0, in_course_at_end = 0;
  // Over goals comforted after their windows: urgency weight times lateness.
  double weighted_lateness = 0.0;
  std::size_t robots_down = 0;  // breakdowns (failure kind robot_down)
  // Soft windows: goals whose senior, looked at again when the window
  // passed, called for another goal.
  std::size_t superseded = 0;
  std::size_t robots = 0;                     // of the home
  std::map<std::string, double> robot_busy_s;  // each robot's time in actions it was told ended
  // Every planner call, a plan found or not (a survivor statistic otherwise).
  std::vector<double> planning_seconds;
  // initial, merge, repair, proactive; none (no initial plan), merge_failed,
  // repair_failed (no plan found, deferred attempts included).
  std::map<std::string, std::vector<double>> planning_by_reason;
  // Scored against the simulation's truth.
  std::size_t episodes = 0, episodes_detected = 0, false_alarms = 0;
  double end_time = 0.0;
  std::map<std::string, RobotBattery> batteries;  // by robot; with batteries only

  nlohmann::json json() const;
};

// Throws std::invalid_argument (bad settings: an unknown strategy, senior,
// observation model) or the loaders' errors naming the file.
// `on_time`: told the simulated time as the run goes (a progress meter).
HomeSummary run_home(const HomeSettings& settings, EventLog& log, const std::function<void(double)>& on_time = {});

// Makes the run's goal source once the home is loaded (its map names the
// seniors); may throw to refuse the home, before the loop starts.
using GoalSourceMaker = std::function<std::unique_ptr<GoalSource>(const HomeMap& map, EventLog& log)>;

// The same loop with goals from `goals` (the simulated seniors are
// home_perception.h) on `clock`; the run ends when t passes
// settings.until or the clock says stop (then mid-plan too).
HomeSummary run_home(const HomeSettings& settings, EventLog& log, const GoalSourceMaker& goals, RunClock& clock,
                     const std::function<void(double)>& on_time = {});

}  // namespace alplan::home
