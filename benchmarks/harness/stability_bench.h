// `alplan bench stability`: replanning against plan repair on a testbed we
// did not design, the IPC 2002 temporal domains Fox, Gerevini, Long and
// Serina used ("Plan stability: replanning versus plan repair", ICAPS 2006:
// DriverLog, Rovers, Depots, Satellite, ZenoTravel). For each problem the
// planner makes a plan; each run executes it in the simulated world up to
// a step drawn at random, perturbs the world or the goals there
// (perturbation.h: a fact, an object, a goal), keeps the perturbation only
// when the rest of the plan no longer works from the perturbed state, and
// hands the same failure to every strategy (a paired design). Measured per
// strategy: whether it repaired, whether its plan is valid from the
// perturbed state (validated here, independently of the planner), the plan
// distance to the old plan's remaining steps (Fox et al.'s measure:
// actions added plus actions removed, multisets of ground actions), whether
// the new plan starts with the old one's next step, the makespan and the
// time. Writes runs.csv, runs.json and summary.md.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "benchmarks/harness/perturbation.h"
#include "repair/repair_strategy.h"

namespace alplan::bench {

struct StabilityBenchOptions {
  std::string ipc_dir;  // holds ipc-2002/...
  std::vector<std::string> domains{"ipc-2002/driverlog-time-automatic", "ipc-2002/rovers-time-automatic",
                                   "ipc-2002/depots-time-simple-automatic",
                                   "ipc-2002/satellite-time-simple-automatic",
                                   "ipc-2002/zenotravel-time-simple-automatic"};
  int first_problem = 1, last_problem = 5;
  int perturbations = 2;  // per problem and kind
  std::vector<PerturbationKind> kinds{PerturbationKind::Fact, PerturbationKind::Object, PerturbationKind::Goal};
  std::vector<std::string> strategies{"replan", "adapt", "stable", "patch"};
  std::uint64_t seed = 1;
  double plan_seconds = 10.0;  // each problem's first plan
  // Draws per run until the perturbation breaks the rest of the plan.
  int draws = 20;
  repair::StrategyOptions strategy;  // every strategy's planner and budgets
  // Per perturbation, stable's minimum distance computed again by a
  // classical compilation solved with A* on LM-cut (stable_cross_check.h),
  // within so many seconds.
  bool cross_check = false;
  double cross_check_seconds = 30.0;
  std::ostream* progress = nullptr;
};

struct StabilityRun {
  std::string domain;  // the folder's name
  int problem = 0;
  int perturbation = 0;
  std::string kind, description;
  double cut = 0.0;                 // when the world changed
  std::size_t old_remaining = 0;    // steps of the old plan still to run
  double old_makespan = 0.0;
  std::string strategy;
  bool repaired = false;  // the strategy returned a plan
  bool valid = false;     // and the plan is valid from the perturbed state
  std::size_t distance = 0, added = 0, removed = 0;
  bool same_first = false;  // the new plan's first step is the old one's next
  std::size_t new_steps = 0;
  double makespan = 0.0;
  double seconds = 0.0;
  int planner_calls = 0;
  std::string fallback, how;
  bool proven = false;  // the strategy says its distance is proven minimal (stable)
  // The perturbation's cross-check (the same on each of its runs): proven,
  // not proven, not comparable; "" when none was asked.
  std::string cross_check_status, cross_check_note;
  std::optional<std::size_t> cross_check_distance;
  double cross_check_seconds = 0.0;
};

struct StabilityBenchResult {
  std::vector<StabilityRun> runs;
  std::vector<std::string> skipped;  // problems or perturbations, with why
};

StabilityBenchResult run_stability_bench(const StabilityBenchOptions& options);

// runs.csv, summary.md, summary.json in `out_dir` (created).
void write_stability_results(const StabilityBenchResult& result, const StabilityBenchOptions& options,
                             const std::string& out_dir);
// The runs a bench wrote (its runs.json), to summarise again; `strategies`
// gets their names in the order they ran.
StabilityBenchResult read_stability_runs(const std::string& runs_json, std::vector<std::string>& strategies);
// The tables of summary.md: per domain and strategy, then against replan.
std::string stability_summary(const StabilityBenchResult& result, const StabilityBenchOptions& options);
// summary.md's section "stable cross-checked" (stable_cross_check.h): per
// perturbation, stable's proven distance against the classical one; empty
// when no run carries a cross-check.
std::string stable_cross_check_section(const StabilityBenchResult& result);

}  // namespace alplan::bench
