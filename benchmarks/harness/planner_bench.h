// `alplan bench planners`: runs our planner on every problem of a suite, one
// process per run under the time and memory limits (as the reference runs
// in shared/benchmarks/baseline were made), validates every plan again with
// `alplan validate`, and reports coverage, IPC quality score and IPC time
// score per domain beside the reference planners of a baseline (baseline.h)
// and other planners run by their command lines (external_planner.h).
//
// Scores (IPC 2008-2014 temporal tracks): quality = reference / ours, the
// reference being the best value any compared planner reached (so at most
// 1); time = 1 within a second, else 1 - log(t)/log(limit), 0 unsolved.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "benchmarks/harness/external_planner.h"
#include "benchmarks/harness/process_runner.h"
#include "benchmarks/harness/slurm_array.h"
#include "benchmarks/harness/test_set_ledger.h"

namespace alplan::bench {

struct PlannerBenchOptions {
  std::string suite;
  std::string out_dir;
  std::string alplan;      // executable: `alplan plan --json`, `alplan validate`
  std::string baseline;    // a baseline folder (baseline.h), "" for none
  // CSV files of reference values per problem beside the baseline's
  // quality_ref.csv (quality_report.h).
  std::vector<std::string> references;
  RunLimits limits;
  int jobs = 1;
  bool progress_bar = false;  // a bar with rate and ETA on the progress stream (a terminal)
  int first = 0;           // only the first N problems of each domain (0: all)
  // Only the problems at these positions of each domain (1-based, inclusive;
  // 0: no bound), after `first`.
  int from = 0, to = 0;
  // Only the domains whose name (the folder under the suite, e.g.
  // ipc-2006/trucks-preferences-complex) begins with one of these; none: all.
  std::vector<std::string> domains;
  bool anytime = false;
  std::string search = "ehc";
  std::string order;       // wastar's ordering, metric or steps ("": the planner's default)
  // More flags for every `alplan plan` run, as given (an ablation:
  // "--no-resource-balance", "--deferred").
  std::vector<std::string> plan_args;
  // Other planners run beside ours on every problem (external_planner.h),
  // each a column of the tables like a baseline's planner.
  std::vector<ExternalPlanner> external;
  // Local, or one role of a Slurm job array (slurm_array.h): the tasks
  // write their runs' plans to out_dir/plans as a local run does.
  ArrayRun array;
  // Where the problems hold a test set (instances 6-10): the ledger's
  // reason, repeat, tree and binary (test_set_ledger.h).
  TestSetRunOptions test_set;
};

// Returns the number of invalid plans (the harness's own failure count);
// 0 after submitting or running an array task. Throws std::runtime_error on
// an unreadable suite or array folder.
int run_planner_bench(const PlannerBenchOptions& options, std::ostream& out, std::ostream& progress);

}  // namespace alplan::bench
