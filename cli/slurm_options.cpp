#include "cli/slurm_options.h"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <iostream>
#include <memory>

#include "benchmarks/harness/process_runner.h"
#include "cli/commands.h"

namespace alplan::cli {

void add_slurm_options(CLI::App* command, SlurmFlags& flags) {
  const std::string group = "Slurm";
  command->add_option("--slurm", flags.submit_dir, "Write a Slurm job array and its manifest into DIR and submit it")
      ->group(group);
  command->add_option("--partition", flags.slurm.partition, "With --slurm: sbatch --partition")->group(group);
  command->add_option("--time", flags.slurm.time, "With --slurm: sbatch --time per array task (e.g. 2:00:00)")
      ->group(group);
  command->add_option("--mem", flags.slurm.mem, "With --slurm: sbatch --mem per array task (e.g. 6G)")->group(group);
  command->add_option("--batch", flags.slurm.batch, "With --slurm: runs per array task")
      ->check(CLI::PositiveNumber)
      ->group(group);
  command->add_flag("--no-submit", flags.no_submit, "With --slurm: write the job script, do not call sbatch")
      ->group(group);
  // Given by the job script and by `alplan bench merge`.
  command->add_option("--slurm-task", flags.task_dir)->group("");
  command->add_option("--slurm-task-index", flags.task_index)->group("");
  command->add_option("--slurm-merge", flags.merge_dir)->group("");
}

bool array_run(const SlurmFlags& flags, const std::string& out_dir, bench::ArrayRun& run, std::string& error) {
  const int roles = !flags.submit_dir.empty() + !flags.task_dir.empty() + !flags.merge_dir.empty();
  if (roles > 1) {
    error = "--slurm, --slurm-task and --slurm-merge exclude each other";
    return false;
  }
  run = bench::ArrayRun{};
  run.slurm = flags.slurm;
  run.slurm.submit = !flags.no_submit;
  if (!flags.submit_dir.empty()) {
    if (out_dir.empty()) {
      error = "--slurm needs --out: a folder the array tasks can write their plans into, on a shared filesystem";
      return false;
    }
    run.role = bench::ArrayRole::submit;
    run.dir = flags.submit_dir;
    run.command = bench::strip_slurm_options(bench::own_command_line());
  } else if (!flags.task_dir.empty()) {
    run.role = bench::ArrayRole::task;
    run.dir = flags.task_dir;
    run.task = flags.task_index;
    if (run.task < 0) {
      const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
      run.task = id ? std::atoi(id) : -1;
    }
    if (run.task < 0) {
      error = "--slurm-task needs --slurm-task-index or SLURM_ARRAY_TASK_ID";
      return false;
    }
  } else if (!flags.merge_dir.empty()) {
    run.role = bench::ArrayRole::merge;
    run.dir = flags.merge_dir;
  }
  return true;
}

namespace {

struct MergeOptions {
  std::string dir;
  bool resubmit = false;
};

int run_merge(const MergeOptions& options) {
  try {
    const bench::ArrayManifest manifest = bench::read_manifest(options.dir);
    const bench::CollectedTasks tasks = bench::collect_tasks(options.dir, manifest);
    if (!tasks.complete()) {
      bench::report_incomplete(manifest, tasks, std::cerr);
      if (options.resubmit) bench::resubmit_tasks(options.dir, tasks, std::cerr);
      else if (!tasks.failed.empty() || !tasks.missing.empty()) std::cerr << "resubmit them: alplan bench merge " << options.dir << " --resubmit\n";
      return kExitInvalid;
    }
    std::cerr << "all " << manifest.tasks.size() << " tasks finished; merging\n";
    const std::string error = bench::exec_merge(options.dir, manifest);  // returns only on failure
    std::cerr << "error: " << error << "\n";
    return kExitInternalError;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

}  // namespace

void add_bench_merge_command(CLI::App* bench, int& exit_code) {
  auto o = std::make_shared<MergeOptions>();
  CLI::App* m = bench->add_subcommand(
      "merge", "Collect a Slurm run's tasks (--slurm DIR) into the tables a local run writes; name what is missing");
  m->add_option("DIR", o->dir, "The folder given to --slurm")->required();
  m->add_flag("--resubmit", o->resubmit, "Submit the failed and missing tasks again");
  m->callback([o, &exit_code] { exit_code = run_merge(*o); });
}

}  // namespace alplan::cli
