#include "home/robot_faults.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "home/home_problem.h"
#include "home/robot_dispatch.h"

namespace alplan::home {
namespace {

// The world's atom that a robot is out of service (its fault report).
repair::AtomKey out_of_order(const std::string& robot) { return {"out_of_order", robot}; }

}  // namespace

RobotFaults::RobotFaults(repair::WorldSimulator& world, const HomeMap& map, const HomeSettings& settings)
    : world_(world), map_(map), settings_(settings) {
  for (const ScriptedBreakdown& b : settings.breakdowns) {
    if (!map.has_robot(b.robot)) throw std::invalid_argument("breakdown of " + b.robot + ": no such robot");
    out_of_service_until_[b.robot] = std::max(out_of_service_until_[b.robot], b.time + settings.robot_repair_s);
    schedule(b.robot, b.time);
  }
}

bool RobotFaults::draw(const repair::ExecutingPlan& plan, const std::function<double()>& coin) {
  const auto& kinds = settings_.failure_kinds;
  if (std::find(kinds.begin(), kinds.end(), "robot_down") == kinds.end() || plan.steps.empty()) return false;
  if (coin() * static_cast<double>(kinds.size()) >= 1.0) return false;
  const std::string robot = robot_of(plan.steps.front().name, map_);
  if (robot.empty()) return false;
  double begin = plan.steps.front().start, end = begin;
  for (const repair::ScheduledAction& s : plan.steps) end = std::max(end, s.end());
  const double at = begin + coin() * (end - begin);
  // One breakdown at a time: a robot down already does not break again.
  double& out_until = out_of_service_until_[robot];
  if (at < out_until) return false;
  out_until = at + settings_.robot_repair_s;
  schedule(robot, at);
  return true;
}

void RobotFaults::schedule(const std::string& robot, double at) {
  repair::ExogenousEvent down, up;
  down.time = at;
  down.atom = out_of_order(robot);
  down.description = robot + " breaks down";
  up = down;
  up.time = at + settings_.robot_repair_s;
  up.value = false;
  up.description = robot + " is back in service";
  world_.schedule({down, up});
}

std::vector<RobotFaults::Report> RobotFaults::hear(double t, const repair::WorldState& believed) {
  std::vector<Report> reports;
  for (const Placed& placed : map_.robots) {
    const std::string& r = placed.name;
    const bool out = world_.holds(out_of_order(r));
    if (out == down(r)) continue;
    reports.push_back({r, out});
    if (out) {
      down_.insert(r);
      down_at_[r] = last_room(r, believed);
      for (const repair::ActionInProgress& a : world_.in_progress()) {
        if (robot_of(a.name, map_) == r) world_.halt(a.name);
      }
      continue;
    }
    down_.erase(r);
    const auto room = down_at_.find(r);
    if (room == down_at_.end() || room->second.empty()) continue;
    repair::ExogenousEvent stands;
    stands.time = t;
    stands.atom = {"be", r, room->second};
    stands.description = r + " stands in " + room->second + " again";
    world_.schedule({stands});
    world_.advance(t);
  }
  return reports;
}

std::string RobotFaults::last_room(const std::string& robot, const repair::WorldState& believed) const {
  if (const auto room = TravelTimes(believed_places(believed)).room_of(robot)) return *room;
  for (const repair::ActionInProgress& a : world_.in_progress()) {
    std::istringstream words(a.name.substr(1));
    std::string schema, who, from;
    if (words >> schema >> who >> from && schema == "move" && who == robot) return from;
  }
  return {};
}

}  // namespace alplan::home
