#include "home/robot_faults.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

#include "home/home_problem.h"
#include "home/robot_dispatch.h"

namespace alplan::home {
namespace {

// The world's atom that a robot is out of service (its fault report).
repair::AtomKey out_of_order(const std::string& robot) { return {"out_of_order", robot}; }

// A uniform draw in [0, 1) from the top 53 bits: the same on every standard
// library, where std's distributions may differ between them.
double unit(std::mt19937_64& random) { return static_cast<double>(random() >> 11) * 0x1.0p-53; }

// FNV-1a of a robot's name: its stream does not move when robots are added
// or reordered (std::hash may differ between libraries).
std::uint64_t name_key(const std::string& name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : name) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

}  // namespace

RobotFaults::RobotFaults(repair::WorldSimulator& world, const HomeMap& map, const HomeSettings& settings)
    : world_(world), map_(map), settings_(settings) {
  for (const ScriptedBreakdown& b : settings.breakdowns) {
    if (!map.has_robot(b.robot)) throw std::invalid_argument("breakdown of " + b.robot + ": no such robot");
    schedule(b.robot, b.time);
  }
  if (settings.breakdown_rate_per_hour <= 0.0) return;
  for (const Placed& robot : map.robots) {
    random_[robot.name].random.seed(settings.seed * 0x9E3779B97F4A7C15ULL ^ name_key(robot.name));
    draw_random_after(robot.name, 0.0);
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
  if (!free_at(robot, at)) return false;  // down then already: it does not break twice
  schedule(robot, at);
  return true;
}

void RobotFaults::draw_random_after(const std::string& robot, double from) {
  RandomBreakdowns& r = random_.at(robot);
  const double mean_gap_s = 3600.0 / settings_.breakdown_rate_per_hour;
  for (double t = from;;) {
    t += -std::log(1.0 - unit(r.random)) * mean_gap_s;
    if (t >= settings_.until) {
      r.next = -1.0;
      return;
    }
    // Down then for another reason: the process is memoryless, so the
    // next draw from here is as good as waiting for the robot's return.
    if (!free_at(robot, t)) continue;
    r.next = t;
    schedule(robot, t);
    return;
  }
}

bool RobotFaults::free_at(const std::string& robot, double at) const {
  const auto it = scheduled_.find(robot);
  if (it == scheduled_.end()) return true;
  const double repair = settings_.robot_repair_s;
  return std::none_of(it->second.begin(), it->second.end(),
                      [&](double other) { return at < other + repair && other < at + repair; });
}

void RobotFaults::schedule(const std::string& robot, double at) {
  scheduled_[robot].push_back(at);
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
  // A random breakdown that has begun: the robot's next is drawn from its
  // return to service.
  for (auto& [robot, r] : random_) {
    if (r.next >= 0.0 && r.next <= t) draw_random_after(robot, r.next + settings_.robot_repair_s);
  }
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
