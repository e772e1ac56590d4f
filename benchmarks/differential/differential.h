// The differential tester: random tasks (random_task.h) given to the planner
// and, where the planner finds no plan, to the brute-force search
// (brute_force.h). A disagreement is any of:
// - invalid_plan: the planner returned a plan the validator rejects (checked
//   again here, from the printed text, by a validator of its own);
// - false_unsolvable: the planner said "no plan exists" and the brute force
//   found one;
// - missed_plan: the planner gave up (search space exhausted, or a limit)
//   on a task the brute force solves;
// - internal_error, unsupported, crash: the planner failed on a task the
//   generator means to be well within what it supports.
// Task k of a run is random_task(seed + k): `--tasks 1 --seed S+k` replays it.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <string>
#include <vector>

#include "benchmarks/differential/brute_force.h"
#include "benchmarks/differential/random_task.h"

namespace alplan::differential {

struct DifferentialOptions {
  std::uint64_t tasks = 100;
  std::uint64_t seed = 1;
  // Stops after this many seconds even if tasks remain (CI's minute).
  double seconds = std::numeric_limits<double>::infinity();
  // Per task, for the planner: generous against the tasks' size.
  double planner_time_limit = 10.0;
  std::size_t planner_node_limit = 200000;
  RandomTaskOptions generator;
  BruteForceOptions brute_force;
  std::string out_dir;  // where each disagreeing task is written ("": nowhere)
};

struct Disagreement {
  std::uint64_t seed = 0;
  std::string kind;            // invalid_plan, false_unsolvable, missed_plan, ...
  std::string planner_status;  // as status_name() prints it
  std::string message;
  std::string plan;            // the planner's (invalid_plan) or the brute force's
  std::string domain, problem;
};

struct DifferentialReport {
  std::uint64_t tasks = 0;
  std::uint64_t planner_solved = 0, planner_unsolvable = 0, planner_exhausted = 0, planner_limit = 0;
  std::uint64_t brute_force_runs = 0, brute_force_solved = 0, brute_force_cut_short = 0;
  std::uint64_t validations = 0;
  double seconds = 0.0;
  std::vector<Disagreement> disagreements;
};

DifferentialReport run_differential(const DifferentialOptions& options, std::ostream& progress);

// One line per count and one paragraph per disagreement.
void print_report(const DifferentialReport& report, std::ostream& out);

}  // namespace alplan::differential
