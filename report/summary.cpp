#include "report/summary.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace alplan::report {
namespace {

void count_senior_event(const Event& e, SeniorSummary& s) {
  if (e.type == "goal") ++s.goals;
  if (e.type == "comforted") {
    ++s.comforted;
    if (bool_field(e.fields, "within_window")) {
      ++s.within_window;
    } else if (e.fields.contains("window_end")) {
      const double late = std::max(0.0, e.time - number_field(e.fields, "window_end"));
      ++s.late;
      s.lateness_total += late;
      s.lateness_max = std::max(s.lateness_max, late);
    }
  }
  if (e.type == "window_missed") ++s.windows_missed;
}

// The lowest level a robot's battery is known to have had: the `battery`
// events' `lowest` (the world's exact lowest) and the levels at action ends.
void count_battery_event(const Event& e, std::map<std::string, BatterySummary>& batteries) {
  const bool report = e.type == "battery";
  if (e.robot.empty() || !(report || (e.type == "action_end" && e.fields.contains("battery")))) return;
  const double level = number_field(e.fields, report ? "lowest" : "battery");
  const auto [it, fresh] = batteries.try_emplace(e.robot, BatterySummary{e.robot, level, 0.0, false});
  BatterySummary& b = it->second;
  b.lowest = std::min(b.lowest, level);
  if (report) {
    b.reserve = number_field(e.fields, "reserve");
    b.below_reserve = b.below_reserve || bool_field(e.fields, "below_reserve");
  }
}

// Each robot's busy spans, from its action_start and action_end events
// (matched by action; an action still running at the end runs to it).
std::vector<RobotUtilisation> utilisation(const EventLog& log, double end_time) {
  std::map<std::string, std::vector<std::pair<double, double>>> spans;
  std::map<std::pair<std::string, std::string>, double> open;  // (robot, action) -> start
  for (const Event& e : log.events) {
    if (e.robot.empty() || (e.type != "action_start" && e.type != "action_end")) continue;
    const std::pair<std::string, std::string> key{e.robot, text_field(e.fields, "action", "")};
    spans[e.robot];  // a robot that acts appears, even with no span closed
    if (e.type == "action_start") {
      open[key] = e.time;
    } else if (const auto it = open.find(key); it != open.end()) {
      spans[e.robot].emplace_back(it->second, e.time);
      open.erase(it);
    }
  }
  for (const auto& [key, start] : open) spans[key.first].emplace_back(start, end_time);
  std::vector<RobotUtilisation> out;
  const auto hours = static_cast<std::size_t>(std::ceil(std::max(end_time, 1e-9) / 3600.0));
  for (auto& [robot, list] : spans) {
    std::sort(list.begin(), list.end());
    RobotUtilisation u;
    u.robot = robot;
    u.busy_share_per_hour.assign(hours, 0.0);
    double covered_to = -1e300;
    for (auto [from, to] : list) {
      from = std::max(from, covered_to);  // overlapping spans count once
      if (to <= from) continue;
      covered_to = to;
      u.busy_seconds += to - from;
      for (std::size_t h = 0; h < hours; ++h) {
        const double lo = std::max(from, 3600.0 * static_cast<double>(h));
        const double hi = std::min(to, 3600.0 * static_cast<double>(h + 1));
        if (hi > lo) u.busy_share_per_hour[h] += (hi - lo) / 3600.0;
      }
    }
    out.push_back(std::move(u));
  }
  return out;
}

}  // namespace

RunSummary summarize(const EventLog& log) {
  RunSummary r;
  std::map<std::string, SeniorSummary> seniors;
  std::map<std::string, StrategySummary> repairs;
  std::map<std::string, BatterySummary> batteries;
  if (log.home) {
    for (const Placement& p : log.home->seniors) seniors[p.name].senior = p.name;
  }
  for (const Event& e : log.events) {
    r.end_time = std::max(r.end_time, e.time);
    // An explanation names the seniors of its mission, a list: not one senior.
    if (!e.senior.empty() && e.type != "explanation") {
      SeniorSummary& s = seniors[e.senior];
      s.senior = e.senior;
      count_senior_event(e, s);
    }
    count_battery_event(e, batteries);
    if (e.type == "plan") ++r.plans;
    if (e.type == "explanation") ++r.explanations;
    if (e.type == "failure") {
      ++r.failures;
      if (bool_field(e.fields, "foreseen")) ++r.foreseen_failures;
    }
    if (e.type == "repair") {
      const std::string name = text_field(e.fields, "strategy", "(unnamed)");
      StrategySummary& s = repairs[name];
      s.strategy = name;
      ++s.attempts;
      if (bool_field(e.fields, "repaired")) ++s.repaired;
      s.seconds += number_field(e.fields, "seconds");
    }
  }
  for (const auto& [name, s] : seniors) {
    r.seniors.push_back(s);
    if (s.goals > 0) ++r.seniors_with_goals;
    r.goals += s.goals;
    r.comforted += s.comforted;
    r.within_window += s.within_window;
    r.windows_missed += s.windows_missed;
  }
  for (const auto& [name, s] : repairs) r.repairs.push_back(s);
  for (const auto& [name, b] : batteries) r.batteries.push_back(b);
  r.robots = utilisation(log, r.end_time);
  return r;
}

}  // namespace alplan::report
