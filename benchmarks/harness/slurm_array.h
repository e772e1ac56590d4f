// A benchmark run spread over a Slurm job array. The command that would run
// the whole suite locally is written down (a manifest) with its tasks' names;
// each array task re-runs that same command for its share (one problem, one
// home, or a small batch), under the same per-run limits as a local run, and
// leaves its result in DIR/tasks/N.json; `alplan bench merge DIR` collects
// the results and re-runs the command once more to write the tables a local
// run writes. Re-running the command, not copying its options, is what keeps
// a Slurm run and a local run of the same suite the same experiment.
//
// DIR (shared between the submitting machine and the nodes, as on any
// cluster) holds manifest.json, job.sbatch (and job-resubmit-K.sbatch),
// logs/task-N.out and tasks/N.json.
#pragma once

#include <functional>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace alplan::bench {

struct SlurmOptions {
  std::string partition;  // passed through to sbatch; empty: the cluster's default
  std::string time;       // sbatch --time per task (e.g. 30, 2:00:00)
  std::string mem;        // sbatch --mem per task (e.g. 6G)
  int batch = 1;          // runs (problems, homes) per array task
  bool submit = true;     // false: write the job script, leave sbatch to the user
  std::string sbatch = "sbatch";
};

// What one invocation of a benchmark command is asked to be.
enum class ArrayRole {
  local,   // the whole suite, here
  submit,  // write the manifest and the job array, and submit it
  task,    // one array task: a share of the suite, result to DIR/tasks/N.json
  merge,   // read every task's result and write the outputs
};

struct ArrayRun {
  ArrayRole role = ArrayRole::local;
  std::string dir;
  int task = -1;  // for ArrayRole::task
  SlurmOptions slurm;
  // This command's own argv without the Slurm options (own_command_line
  // and strip_slurm_options): what the tasks and the merge re-run.
  std::vector<std::string> command;
};

struct ArrayManifest {
  std::string kind;                     // planners, repair
  std::string working_dir;              // where the command was given (relative paths)
  std::vector<std::string> command;
  std::vector<std::string> tasks;       // a name per array task, for reports
  std::vector<std::string> job_ids;     // every submission, the first and resubmissions
  SlurmOptions slurm;
};

// The argv without --slurm, --partition, --time, --mem, --batch and
// --no-submit (and their values, given as "--opt V" or "--opt=V").
std::vector<std::string> strip_slurm_options(const std::vector<std::string>& argv);

// Writes DIR/manifest.json and DIR/job.sbatch for all of the manifest's
// tasks and, when `slurm.submit`, submits it. Prints what it did and how to
// merge. Throws std::runtime_error when DIR cannot be written or sbatch fails.
void submit_array(const std::string& dir, ArrayManifest manifest, std::ostream& out);

ArrayManifest read_manifest(const std::string& dir);

// Array tasks for `items` runs in batches: task t runs [first, last).
int array_tasks(int items, int batch);
std::pair<int, int> task_items(int task, int items, int batch);

// A task's result, written atomically (a task killed while writing leaves
// no half file), and its failure, written when the task's own code throws.
void write_task_result(const std::string& dir, int task, const nlohmann::json& result);
void write_task_failure(const std::string& dir, int task, const std::string& error);

// Runs a task's body; when it throws, records why (write_task_failure), so
// that merge names the error, and throws on.
void run_array_task(const std::string& dir, int task, const std::function<void()>& body);

struct CollectedTasks {
  std::map<int, nlohmann::json> results;    // finished
  std::map<int, std::string> failed;        // what went wrong (its error, or its log's last line)
  std::vector<int> pending;                 // still queued or running, as squeue tells
  std::vector<int> missing;                 // never ran, or left nothing
  bool complete() const { return failed.empty() && pending.empty() && missing.empty(); }
};

CollectedTasks collect_tasks(const std::string& dir, const ArrayManifest& manifest);

// Prints the failed, pending and missing tasks by name; empty when complete.
void report_incomplete(const ArrayManifest& manifest, const CollectedTasks& tasks, std::ostream& out);

// Submits the failed and missing tasks again (job-resubmit-K.sbatch).
void resubmit_tasks(const std::string& dir, const CollectedTasks& tasks, std::ostream& out);

// Replaces this process with the manifest's command in merge role, run from
// the manifest's working directory. Returns only on failure (errno's text).
std::string exec_merge(const std::string& dir, const ArrayManifest& manifest);

}  // namespace alplan::bench
