// `alplan bench repair`: generates homes, injects the same failures into the
// same executions for every strategy, and compares the strategies: success
// rate, repair latency (median, p95), plan stability (actions removed plus
// added, Fox et al. 2006), delay until the senior is comforted, makespan,
// cost, planner calls. Optionally the same repairs through a planner in
// another process (the paper's architecture), for the latency ratio.
// Writes runs.csv, runs.json, summary.md, summary.json and one SVG per metric.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "domains/home_generator.h"
#include "repair/random_events.h"
#include "repair/repair_strategy.h"

namespace alplan::bench {

struct RepairBenchOptions {
  int homes = 10;
  int failures_per_run = 1;
  // The kinds of failure to draw and how (repair/random_events.h); the
  // seed is replaced per run, from the home's seed and the run's number.
  repair::RandomEventOptions events;
  int runs_per_home = 3;
  std::uint64_t seed = 1;
  std::vector<std::string> strategies{"replan", "substitute", "suggest", "patch", "adapt"};
  domains::HomeOptions home;  // its seed is replaced per home
  std::string assisted_living_dir;
  std::string out_dir;
  bool external = false;  // also replan through `alplan plan` in a child process
  std::string alplan;     // the executable, for the external runs
  double epsilon = 0.001;
  double planning_time = 10.0;
  // The monitor grounds each home once when execution starts and repairs
  // reuse that grounding when they can (repair/monitor.h); off, every
  // repair grounds its problem from scratch, as the external planner must.
  bool reuse_grounding = true;
  // The strategies' own knobs (adapt's search); their planner's epsilon
  // and time come from the fields above.
  repair::StrategyOptions strategy_options;
};

// Returns the exit code: 0, or 2 for bad options or unwritable output.
int run_repair_bench(const RepairBenchOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace alplan::bench
