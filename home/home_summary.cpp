// HomeSummary's figures (home_run.h). Latency quantiles are nearest ranks
// (stats/quantile.h) over every planner call, failed ones included; none for
// no call (null in JSON).
#include "home/home_run.h"
#include "stats/quantile.h"

namespace alplan::home {
namespace {

// A quantile of no call is no number: null, never 0 (a latency nobody had).
nlohmann::json nearest_rank_or_null(const std::vector<double>& seconds, double q) {
  if (seconds.empty()) return nullptr;
  return stats::nearest_rank(seconds, q);
}

}  // namespace

nlohmann::json HomeSummary::json() const {
  nlohmann::json j = {{"goals", goals},         {"comforted", comforted},     {"within_window", within_window},
          {"windows_missed", windows_missed}, {"failures", failures}, {"plans", plans},
          {"merges", merges},       {"repairs", repairs},         {"repairs_failed", repairs_failed},
          {"objects_recognized", objects_recognized},
          {"planning_p50_s", nearest_rank_or_null(planning_seconds, 0.5)},
          {"planning_p95_s", nearest_rank_or_null(planning_seconds, 0.95)},
          {"episodes", episodes},   {"episodes_detected", episodes_detected}, {"false_alarms", false_alarms}, {"end_time", end_time},
          {"never_served", never_served}, {"in_course_at_end", in_course_at_end}, {"weighted_lateness", weighted_lateness},
          {"robots_down", robots_down}, {"robots", robots}, {"robot_busy_s", robot_busy_s}, {"superseded", superseded}};
  if (batteries.empty()) return j;  // runs without batteries: as before
  nlohmann::json& b = j["batteries"];
  for (const auto& [robot, r] : batteries) {
    b[robot] = {{"level", r.level}, {"lowest", r.lowest}, {"reserve", r.reserve}, {"below_reserve", r.below_reserve}};
  }
  return j;
}

}  // namespace alplan::home
