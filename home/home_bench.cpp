#include "home/home_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace alplan::home {
namespace {

nlohmann::json latency(const std::vector<double>& seconds) {
  return {{"plans", seconds.size()},
          {"p50_s", quantile(seconds, 0.5)},
          {"p95_s", quantile(seconds, 0.95)},
          {"max_s", quantile(seconds, 1.0)}};
}

std::string row(const std::string& what, const std::vector<double>& seconds) {
  char line[160];
  std::snprintf(line, sizeof line, "| %-28s | %6zu | %8.3f | %8.3f | %8.3f |\n", what.c_str(), seconds.size(),
                quantile(seconds, 0.5), quantile(seconds, 0.95), quantile(seconds, 1.0));
  return line;
}

}  // namespace

nlohmann::json HomeBenchResult::json(const HomeSettings& settings) const {
  nlohmann::json by_reason = nlohmann::json::object();
  for (const auto& [reason, seconds] : summary.planning_by_reason) by_reason[reason] = latency(seconds);
  std::vector<double> replanning;
  for (const char* r : {"merge", "repair"}) {
    const auto it = summary.planning_by_reason.find(r);
    if (it != summary.planning_by_reason.end()) replanning.insert(replanning.end(), it->second.begin(), it->second.end());
  }
  const double goals = static_cast<double>(std::max<std::size_t>(1, summary.goals));
  return {{"settings", settings.json()},
          {"summary", summary.json()},
          {"planning", latency(summary.planning_seconds)},
          {"replanning", latency(replanning)},
          {"planning_by_reason", by_reason},
          {"comforted_within_window_share", static_cast<double>(summary.within_window) / goals},
          {"wall_seconds", wall_seconds},
          {"simulated_per_wall_second", settings.until / std::max(1e-9, wall_seconds)},
          {"events", events}};
}

HomeBenchResult run_home_bench(const HomeSettings& settings, const std::function<void(double)>& on_time) {
  HomeBenchResult result;
  EventLog log;
  const auto began = std::chrono::steady_clock::now();
  result.summary = run_home(settings, log, on_time);
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  result.events = log.events().size();
  return result;
}

void print_home_bench(std::ostream& out, const HomeSettings& settings, const HomeBenchResult& r) {
  const HomeSummary& s = r.summary;
  out << "| planning (seconds, wall)     | plans  |      p50 |      p95 |      max |\n"
      << "|------------------------------|--------|----------|----------|----------|\n";
  std::vector<double> replanning;
  for (const auto& [reason, seconds] : s.planning_by_reason) {
    out << row(reason == "none" ? "no plan found" : reason, seconds);
    if (reason == "merge" || reason == "repair") replanning.insert(replanning.end(), seconds.begin(), seconds.end());
  }
  out << row("replanning (merge + repair)", replanning) << row("every planner call", s.planning_seconds);
  char line[400];
  std::snprintf(line, sizeof line,
                "\n%zu goals: %zu comforted within their windows (%.1f%%), %zu late, %zu windows missed; "
                "%zu failures, %zu repairs failed\n%.0f simulated s in %.1f wall s (%.0fx); scored against the "
                "simulation: %zu stress episodes, %zu detected, %zu false alarms\n",
                s.goals, s.within_window, 100.0 * static_cast<double>(s.within_window) / static_cast<double>(std::max<std::size_t>(1, s.goals)),
                s.comforted - s.within_window, s.windows_missed, s.failures, s.repairs_failed, settings.until,
                r.wall_seconds, settings.until / std::max(1e-9, r.wall_seconds), s.episodes, s.episodes_detected, s.false_alarms);
  out << line;
}

}  // namespace alplan::home
