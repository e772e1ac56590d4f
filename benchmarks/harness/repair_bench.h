// `alplan bench repair`: generates homes, injects the same failures into the
// same executions for every strategy (a paired design), executes them under
// the monitor's observation model, and compares the strategies per failure
// kind with paired statistics (repair_study.h). Optionally the same repairs
// through a planner in another process (the paper's architecture), for the
// latency ratio. Writes runs.csv, runs.json, summary.md, summary.json and
// plots/*.svg.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "stats/paired_comparison.h"
#include "benchmarks/harness/repair_study.h"
#include "benchmarks/harness/slurm_array.h"
#include "domains/home_generator.h"
#include <nlohmann/json.hpp>

#include "repair/object_recognizer.h"
#include "repair/observation.h"
#include "repair/random_events.h"
#include "repair/repair_strategy.h"

namespace alplan::bench {

struct RepairBenchOptions {
  int homes = 40;
  int failures_per_run = 1;
  // The kinds of failure to draw and how (repair/random_events.h); the
  // seed is replaced per run, from the home's seed and the run's number.
  repair::RandomEventOptions events;
  int runs_per_home = 5;
  std::uint64_t seed = 1;
  std::vector<std::string> strategies{"replan", "substitute", "suggest", "patch", "adapt", "switch"};
  domains::HomeOptions home;  // its seed is replaced per home
  std::string assisted_living_dir;
  std::string out_dir;
  bool progress_bar = false;  // a bar with rate and ETA on the progress stream (a terminal)
  bool external = false;  // also replan through `alplan plan` in a child process
  std::string alplan;     // the executable, for the external runs
  double epsilon = 0.001;
  double planning_time = 10.0;
  double initial_planning_time = 1.0;  // anytime, for each home's first plan
  // Each weight of that anytime search capped at so many expansions (0: by
  // time alone); set, the first plans do not depend on the machine's speed.
  std::uint64_t initial_expansions = 0;
  // The repairs' planner: anytime down to this weight, each weight capped
  // at so many expansions (PlannerOptions), for every strategy alike.
  bool repair_anytime = true;
  double repair_min_weight = 3.0;
  std::uint64_t repair_expansions = 1000;
  // The monitor grounds each home once when execution starts and repairs
  // reuse that grounding when they can (repair/monitor.h); off, every
  // repair grounds its problem from scratch, as the external planner must.
  bool reuse_grounding = true;
  // The strategies' own knobs (adapt's search); their planner's epsilon
  // and time come from the fields above.
  repair::StrategyOptions strategy_options;
  // What the monitor sees of the world (iot: the paper's sensors).
  repair::ObservationOptions observation;
  stats::BootstrapOptions bootstrap;
  bool paper_home = true;  // also time the strategies on the paper's three scenarios
  // The camera: wraps the simulator (which knows each thing's type) with a
  // real recognizer (perception/vision/drawing_camera.h); none: the simulator
  // names things itself, perfectly and at no cost. `camera_info` goes into
  // the summary.
  std::function<std::unique_ptr<repair::ObjectRecognizer>(repair::ObjectRecognizer& truth)> camera;
  nlohmann::json camera_info;
  // Local, or one role of a Slurm job array (slurm_array.h): a task runs
  // a batch of homes (the paper's home is the last item when timed).
  ArrayRun array;
};

// Returns the exit code: 0, or 2 for bad options or unwritable output.
int run_repair_bench(const RepairBenchOptions& options, std::ostream& out, std::ostream& progress);

// The runs a study wrote (its runs.json), as the analysis reads them.
std::vector<StudyRun> load_study_runs(const std::string& runs_json);

}  // namespace alplan::bench
