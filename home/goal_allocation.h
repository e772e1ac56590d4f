// Which robot serves each new goal (issue 31): task allocation with
// per-robot planning. A goal goes to the robot, idle or busy, that the
// estimate says reaches the senior with the least weighted lateness, the
// earliest arrival breaking ties (so an idle robot wins when no window is
// at stake); a busy robot's estimate starts when its plan in force ends,
// from the room of the last senior it serves. Goals are placed most urgent
// first (weight, then window), each placement moving the chosen robot's
// estimate on by the goal's travel and a service time: the greedy
// insertion heuristic of multi-robot task allocation (Gerkey and Mataric,
// "A formal analysis and taxonomy of task allocation in multi-robot
// systems", IJRR 23(9), 2004, the ST-SR-TA case with time windows).
//
// The estimate is travel only (home/robot_dispatch.h's times) plus the
// service time: it is cheap enough for every new goal, and the planner
// decides the real schedule; the allocation only says who.
#pragma once

#include <string>
#include <vector>

#include "home/robot_dispatch.h"

namespace alplan::home {

// A robot the allocation may give goals to.
struct RobotLoad {
  std::string robot;
  std::string room;     // where it is when free: where it stands, or its last senior's room
  double free_at = 0.0;  // now when idle; when its plan in force ends when busy
  bool idle = true;
};

struct GoalRequest {
  std::string senior;
  double window_end = 0.0;
  double weight = 1.0;  // urgency (HomeSettings::urgency_weights)
  std::vector<std::string> refused_by;  // robots whose plans could not take it in
};

struct Assignment {
  std::size_t goal = 0;  // index into the requests
  std::string robot;
  double arrival = 0.0;  // estimated
  bool to_idle = true;   // the robot was idle before this round
};

struct AllocationOptions {
  double now = 0.0;
  double service_s = 120.0;  // fetching the remedy and handing it over, beyond the travel
};

// One assignment per goal that some robot can reach (a robot that refused
// it, or with no known room, is no candidate); goals no robot can reach
// are left out. Deterministic: ties go to the robot listed first.
std::vector<Assignment> allocate_goals(const TravelTimes& travel, std::vector<RobotLoad> robots,
                                       const std::vector<GoalRequest>& goals, const AllocationOptions& options);

}  // namespace alplan::home
