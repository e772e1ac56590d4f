#include "home/goal_allocation.h"

#include <algorithm>
#include <limits>
#include <numeric>

namespace alplan::home {

std::vector<Assignment> allocate_goals(const TravelTimes& travel, std::vector<RobotLoad> robots,
                                       const std::vector<GoalRequest>& goals, const AllocationOptions& options) {
  std::vector<std::size_t> order(goals.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (goals[a].weight != goals[b].weight) return goals[a].weight > goals[b].weight;
    return goals[a].window_end < goals[b].window_end;
  });
  std::vector<Assignment> out;
  for (const std::size_t g : order) {
    const GoalRequest& goal = goals[g];
    const std::optional<std::string> room = travel.room_of(goal.senior);
    if (!room) continue;
    const std::map<std::string, double> to_senior = travel.times_to(*room);
    RobotLoad* best = nullptr;
    double best_lateness = 0.0, best_arrival = 0.0;
    for (RobotLoad& r : robots) {
      if (std::find(goal.refused_by.begin(), goal.refused_by.end(), r.robot) != goal.refused_by.end()) continue;
      const auto travel_time = to_senior.find(r.room);
      if (travel_time == to_senior.end()) continue;
      const double arrival = std::max(r.free_at, options.now) + travel_time->second;
      const double lateness = goal.weight * std::max(0.0, arrival - goal.window_end);
      if (!best || lateness < best_lateness || (lateness == best_lateness && arrival < best_arrival)) {
        best = &r;
        best_lateness = lateness;
        best_arrival = arrival;
      }
    }
    if (!best) continue;
    out.push_back({g, best->robot, best_arrival, best->idle});
    best->free_at = best_arrival + options.service_s;
    best->room = *room;
  }
  return out;
}

}  // namespace alplan::home
