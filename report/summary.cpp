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

}  // namespace

RunSummary summarize(const EventLog& log) {
  RunSummary r;
  std::map<std::string, SeniorSummary> seniors;
  std::map<std::string, StrategySummary> repairs;
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
  return r;
}

}  // namespace alplan::report
