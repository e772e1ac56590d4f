// Robots that break down (the home's failure kind robot_down, issue 31).
// The simulation's side: a breakdown scripted in the settings, drawn
// within a new plan, or at random (settings.breakdown_rate_per_hour, issue
// 43), the robot's actions halted where they are (their ends never come),
// and the robot standing again where it broke down robot_repair_s later;
// one breakdown of a robot at a time. The home's side: each robot's own fault report,
// heard at the home's next look; the home knows nothing else of the world
// from it.
#pragma once

#include <functional>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "home/home_map.h"
#include "home/home_settings.h"
#include "repair/executing_plan.h"
#include "repair/world_simulator.h"

namespace alplan::home {

class RobotFaults {
 public:
  // Schedules the settings' breakdowns; throws std::invalid_argument naming
  // a robot the home lacks.
  RobotFaults(repair::WorldSimulator& world, const HomeMap& map, const HomeSettings& settings);

  // With "robot_down" among the failure kinds, drawn as often as each other
  // kind (`coin` in [0, 1)): the plan's first robot breaks down at a time
  // drawn over the plan's span, unless it is out of service then already.
  // Returns whether a breakdown was drawn.
  bool draw(const repair::ExecutingPlan& plan, const std::function<double()>& coin);

  struct Report {
    std::string robot;
    bool down = false;  // false: back in service
  };
  // The reports that changed since the last look, in the home's robot order.
  // A robot reported down has its running actions halted; one back stands
  // where it broke down (as the belief had it, or where its halted move began).
  std::vector<Report> hear(double t, const repair::WorldState& believed);

  bool down(const std::string& robot) const { return down_.count(robot) != 0; }

 private:
  // Breakdowns at random: while in service, each robot breaks down at the
  // rate per hour whatever it is doing (a Poisson process in service time:
  // care home robots fail working and idle alike), so the gaps between
  // breakdowns are robot_repair_s plus an exponential draw. Drawn one at a
  // time, the next when the last has begun (a live run has no end to draw
  // up to), each robot from its own stream keyed by its name and the seed.
  struct RandomBreakdowns {
    std::mt19937_64 random;
    double next = -1.0;  // the one scheduled; negative: none left in the run
  };
  void draw_random_after(const std::string& robot, double from);
  // No breakdown of `robot` scheduled overlaps one at `at`.
  bool free_at(const std::string& robot, double at) const;
  void schedule(const std::string& robot, double at);
  std::string last_room(const std::string& robot, const repair::WorldState& believed) const;

  repair::WorldSimulator& world_;
  const HomeMap& map_;
  const HomeSettings& settings_;
  std::set<std::string> down_;                         // as reported
  std::map<std::string, std::string> down_at_;         // where each broke down
  std::map<std::string, std::vector<double>> scheduled_;  // the simulation's: each robot's breakdowns
  std::map<std::string, RandomBreakdowns> random_;        // with a breakdown rate
};

}  // namespace alplan::home
