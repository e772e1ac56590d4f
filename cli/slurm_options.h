// The Slurm options that `alplan bench planners` and `alplan bench repair`
// share (benchmarks/harness/slurm_array.h): --slurm DIR with --partition,
// --time, --mem, --batch and --no-submit to write and submit a job array;
// --slurm-task DIR --slurm-task-index N and --slurm-merge DIR, which the
// job script and `alplan bench merge` give, not people.
#pragma once

#include <string>

#include "benchmarks/harness/slurm_array.h"

namespace CLI {
class App;
}

namespace alplan::cli {

struct SlurmFlags {
  std::string submit_dir, task_dir, merge_dir;
  int task_index = -1;
  bool no_submit = false;
  bench::SlurmOptions slurm;
};

void add_slurm_options(CLI::App* command, SlurmFlags& flags);

// The harness's role for these flags; false with `error` set when they
// contradict each other.
bool array_run(const SlurmFlags& flags, const std::string& out_dir, bench::ArrayRun& run, std::string& error);

// `alplan bench merge DIR [--resubmit]`.
void add_bench_merge_command(CLI::App* bench, int& exit_code);

}  // namespace alplan::cli
