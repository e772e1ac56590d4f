// The analysis of `alplan bench repair`: a paired study of repair
// strategies. Every strategy meets the same failures in the same homes, so
// each is compared with a reference (replan) run by run: per failure kind
// and over all, success rate, repair latency (median, p95), plan stability
// (Fox, Gerevini, Long & Serina, ICAPS 2006: actions removed plus added),
// delay until the senior is comforted, makespan, cost and planner calls;
// every run counted (intention to treat): the metrics every run has as
// paired differences, those that mean something only for a comforted run
// (stability, delay, makespan, cost, metric) as a net benefit with success first (Buyse 2010,
// stats/prioritized_comparison.h); each with a 95% cluster bootstrap
// interval, paired tests on the per-home means and effect sizes
// (stats/paired_comparison.h: a home's runs are not independent, so the
// home is the unit), the signed-rank p-values Holm-adjusted (Holm 1979)
// over all strategies and metrics of one failure kind; then where each
// strategy wins. The comforted-only metrics on the runs both comforted are
// a labelled secondary table (json against_<reference>_common_set). A pure function of the runs, so a
// test can feed it runs made by hand.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "stats/paired_comparison.h"

namespace alplan::bench {

// One execution of one strategy against one run's failures.
struct StudyRun {
  std::string home;
  int run = 0;
  std::string strategy;
  std::string kind;  // the failure kind drawn (random_events.h)
  bool comforted = false;
  std::vector<double> latencies_ms;  // one per repair attempt, perception included
  double perception_ms = 0.0;        // of the latencies
  double stability = 0.0;            // actions removed plus added, over the run's repairs
  int planner_calls = 0;
  std::size_t repairs = 0;
  std::optional<double> delay, makespan, cost;  // runs that comforted the senior
};

struct StudyAnalysis {
  nlohmann::json json;        // per kind, per strategy, per metric
  std::string markdown;       // the tables people read
  std::map<std::string, std::string> plots;  // file name -> SVG
};

// `strategies` in the order to report; `reference` among them. A verdict
// (json kinds.<kind>.against_<reference>.<strategy>.<metric>.verdict and
// wins.<kind>.<metric>.<strategy>) is "better" or "worse" only when the
// cluster interval excludes zero and the Holm-adjusted p is below 0.05,
// else "tie".
StudyAnalysis analyse_repair_study(const std::vector<StudyRun>& runs, const std::vector<std::string>& strategies,
                                   const std::string& reference, const stats::BootstrapOptions& bootstrap);

}  // namespace alplan::bench
