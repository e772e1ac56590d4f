#include "home/home_bench.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

#include "stats/quantile.h"

namespace alplan::home {
namespace {

// Nearest ranks (stats/quantile.h): each a time some call took. None for no
// call: null in JSON, "-" in the table.
nlohmann::json latency(const std::vector<double>& seconds) {
  const auto rank = [&](double q) -> nlohmann::json {
    if (seconds.empty()) return nullptr;
    return stats::nearest_rank(seconds, q);
  };
  return {{"plans", seconds.size()}, {"p50_s", rank(0.5)}, {"p95_s", rank(0.95)}, {"max_s", rank(1.0)}};
}

std::string seconds_cell(const std::vector<double>& seconds, double q) {
  if (seconds.empty()) return "-";
  char cell[32];
  std::snprintf(cell, sizeof cell, "%.3f", stats::nearest_rank(seconds, q));
  return cell;
}

std::string row(const std::string& what, const std::vector<double>& seconds) {
  char line[200];
  std::snprintf(line, sizeof line, "| %-28s | %6zu | %8s | %8s | %8s |\n", what.c_str(), seconds.size(),
                seconds_cell(seconds, 0.5).c_str(), seconds_cell(seconds, 0.95).c_str(),
                seconds_cell(seconds, 1.0).c_str());
  return line;
}

// A call that found no plan: its time is the time to the failure.
bool is_failure(const std::string& reason) {
  return reason == "none" || reason == "merge_failed" || reason == "repair_failed";
}

// Every call of the reasons `keep` accepts.
std::vector<double> calls(const HomeSummary& summary, const std::function<bool(const std::string&)>& keep) {
  std::vector<double> out;
  for (const auto& [reason, seconds] : summary.planning_by_reason) {
    if (keep(reason)) out.insert(out.end(), seconds.begin(), seconds.end());
  }
  return out;
}

// Replanning: merges and repairs, the calls that found no plan included.
bool is_replanning(const std::string& reason) {
  return reason == "merge" || reason == "repair" || reason == "merge_failed" || reason == "repair_failed";
}

std::vector<double> replanning_seconds(const HomeSummary& summary) { return calls(summary, is_replanning); }

// part / whole, 0 for no whole.
double share(std::size_t part, std::size_t whole) {
  return static_cast<double>(part) / static_cast<double>(std::max<std::size_t>(1, whole));
}

std::string reason_label(const std::string& reason) {
  if (reason == "none") return "no initial plan found";
  if (reason == "merge_failed") return "merge, no plan found";
  if (reason == "repair_failed") return "repair, no plan found";
  return reason;
}

// The robots' mean share of the run spent in actions.
double utilisation(const HomeSummary& s) {
  double busy = 0.0;
  for (const auto& [robot, seconds] : s.robot_busy_s) busy += seconds;
  return busy / std::max(1e-9, static_cast<double>(std::max<std::size_t>(1, s.robots)) * s.end_time);
}

}  // namespace

nlohmann::json HomeBenchResult::json(const HomeSettings& settings) const {
  nlohmann::json by_reason = nlohmann::json::object();
  for (const auto& [reason, seconds] : summary.planning_by_reason) by_reason[reason] = latency(seconds);
  const std::vector<double> replanning = replanning_seconds(summary);
  return {{"settings", settings.json()},
          {"summary", summary.json()},
          {"planning", latency(summary.planning_seconds)},
          {"replanning", latency(replanning)},
          {"planning_found", latency(calls(summary, [](const std::string& r) { return !is_failure(r); }))},
          {"planning_failed", latency(calls(summary, is_failure))},
          {"planning_by_reason", by_reason},
          // Every call's seconds by reason: a reader computes any quantile again.
          {"planning_seconds_by_reason", summary.planning_by_reason},
          {"comforted_within_window_share", share(summary.within_window, summary.goals)},
          {"meetable_goals", summary.meetable},
          {"meetable_within_window_share", share(summary.meetable_within_window, summary.meetable)},
          {"never_served", summary.never_served},
          {"in_course_at_end", summary.in_course_at_end},
          {"weighted_lateness_s", summary.weighted_lateness},
          {"robot_utilisation", utilisation(summary)},
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
  out << "| planning (seconds, wall)     | calls  |      p50 |      p95 |      max |\n"
      << "|------------------------------|--------|----------|----------|----------|\n";
  for (const auto& [reason, seconds] : s.planning_by_reason) out << row(reason_label(reason), seconds);
  out << row("replanning, failed included", replanning_seconds(s))
      << row("calls that found a plan", calls(s, [](const std::string& reason) { return !is_failure(reason); }))
      << row("calls that found none", calls(s, is_failure)) << row("every planner call", s.planning_seconds);
  char line[400];
  std::snprintf(line, sizeof line,
                "\n%zu goals: %zu comforted within their windows (%.1f%%), %zu late, %zu windows missed; "
                "%zu failures, %zu repairs failed\n%.0f simulated s in %.1f wall s (%.0fx); scored against the "
                "simulation: %zu stress episodes, %zu detected, %zu false alarms\n",
                s.goals, s.within_window, 100.0 * share(s.within_window, s.goals),
                s.comforted - s.within_window, s.windows_missed, s.failures, s.repairs_failed, settings.until,
                r.wall_seconds, settings.until / std::max(1e-9, r.wall_seconds), s.episodes, s.episodes_detected, s.false_alarms);
  out << line;
  if (settings.score_meetable) {
    std::snprintf(line, sizeof line,
                  "of the %zu goals one idle robot could have met alone, %zu within their windows (%.1f%%)\n",
                  s.meetable, s.meetable_within_window, 100.0 * share(s.meetable_within_window, s.meetable));
    out << line;
  }
  std::snprintf(line, sizeof line,
                "%zu goals never served (their windows closed first), %zu in course at the end; weighted lateness "
                "%.0f s; robots at work %.1f%% of the time (%s fleet), %zu breakdowns\n",
                s.never_served, s.in_course_at_end, s.weighted_lateness,
                100.0 * utilisation(s), settings.fleet.c_str(), s.robots_down);
  out << line;
}

}  // namespace alplan::home
