#include "report/summary.h"

#include <algorithm>
#include <map>

namespace alplan::report {
namespace {

void count_senior_event(const Event& e, SeniorSummary& s) {
  if (e.type == "goal") ++s.goals;
  if (e.type == "comforted") {
    ++s.comforted;
    if (bool_field(e.fields, "within_window")) ++s.within_window;
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
    if (!e.senior.empty()) {
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
  return r;
}

}  // namespace alplan::report
