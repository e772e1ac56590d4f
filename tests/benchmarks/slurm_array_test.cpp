#include "benchmarks/harness/slurm_array.h"

#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace alplan::bench;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh folder per test, so that tests can run side by side.
fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("alplan_slurm_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

ArrayManifest three_tasks(const fs::path& dir) {
  ArrayManifest m;
  m.kind = "planners";
  m.working_dir = dir.string();
  m.command = {"/opt/alplan", "bench", "planners", "--suite", "it's here", "--out", "out"};
  m.tasks = {"d/instance-1.pddl", "d/instance-2.pddl", "d/instance-3.pddl"};
  m.slurm.submit = false;
  m.slurm.partition = "short";
  m.slurm.mem = "6G";
  m.slurm.time = "10:00";
  return m;
}

}  // namespace

TEST_CASE("the Slurm options are taken out of the command the tasks re-run") {
  const std::vector<std::string> argv{"/bin/alplan", "bench", "planners", "--suite", "s", "--slurm", "D",
                                      "--partition=short", "--time", "1:00", "--mem", "4G", "--batch", "3",
                                      "--no-submit", "--time-limit", "60", "--out", "o"};
  const std::vector<std::string> expected{"/bin/alplan", "bench", "planners", "--suite", "s",
                                          "--time-limit", "60", "--out", "o"};
  CHECK(strip_slurm_options(argv) == expected);
}

TEST_CASE("runs are shared out in batches, the last one shorter") {
  CHECK(array_tasks(7, 3) == 3);
  CHECK(array_tasks(6, 3) == 2);
  CHECK(array_tasks(5, 1) == 5);
  CHECK(array_tasks(0, 2) == 0);
  CHECK(task_items(0, 7, 3) == std::pair<int, int>{0, 3});
  CHECK(task_items(2, 7, 3) == std::pair<int, int>{6, 7});
  CHECK(task_items(3, 7, 3) == std::pair<int, int>{7, 7});
}

TEST_CASE("the job script re-runs the command in task role with the sbatch options") {
  const fs::path dir = fresh_dir("script");
  std::ostringstream out;
  submit_array(dir.string(), three_tasks(dir), out);
  const std::string script = read(dir / "job.sbatch");
  CHECK(script.find("#SBATCH --array=0-2\n") != std::string::npos);
  CHECK(script.find("#SBATCH --partition=short\n") != std::string::npos);
  CHECK(script.find("#SBATCH --mem=6G\n") != std::string::npos);
  CHECK(script.find("#SBATCH --time=10:00\n") != std::string::npos);
  CHECK(script.find("#SBATCH --chdir=" + dir.string() + "\n") != std::string::npos);
  // Quoted for the shell, a quote inside an argument too.
  CHECK(script.find("exec '/opt/alplan' 'bench' 'planners' '--suite' 'it'\\''s here'") != std::string::npos);
  CHECK(script.find("--slurm-task '" + dir.string() + "' --slurm-task-index \"$SLURM_ARRAY_TASK_ID\"") !=
        std::string::npos);
  CHECK(out.str().find("not submitted") != std::string::npos);
  const ArrayManifest back = read_manifest(dir.string());
  CHECK(back.command == three_tasks(dir).command);
  CHECK(back.tasks.size() == 3);
  CHECK(back.slurm.partition == "short");
  // A folder holding results is not overwritten by a second submission.
  write_task_result(dir.string(), 0, nlohmann::json::array());
  CHECK_THROWS_WITH(submit_array(dir.string(), three_tasks(dir), out), Catch::Contains("already holds results"));
  fs::remove_all(dir);
}

TEST_CASE("merge tells finished, failed and missing tasks apart and resubmits only the unfinished") {
  const fs::path dir = fresh_dir("collect");
  std::ostringstream out;
  submit_array(dir.string(), three_tasks(dir), out);
  write_task_result(dir.string(), 0, nlohmann::json{{"runs", 1}});
  // Task 1 was killed by Slurm: a log and no result.
  std::ofstream(dir / "logs" / "task-1.out") << "[1/1] d instance-2.pddl\nslurmstepd: error: *** JOB 9 CANCELLED DUE TO TIME LIMIT ***\n";
  const ArrayManifest m = read_manifest(dir.string());
  CollectedTasks c = collect_tasks(dir.string(), m);
  CHECK_FALSE(c.complete());
  CHECK(c.results.size() == 1);
  CHECK(c.results.at(0).at("runs") == 1);
  REQUIRE(c.failed.count(1) == 1);
  CHECK(c.failed.at(1).find("TIME LIMIT") != std::string::npos);
  CHECK(c.missing == std::vector<int>{2});
  std::ostringstream report;
  report_incomplete(m, c, report);
  CHECK(report.str().find("failed: task 1 (d/instance-2.pddl)") != std::string::npos);
  CHECK(report.str().find("missing: task 2 (d/instance-3.pddl)") != std::string::npos);

  std::ostringstream resubmitted;
  resubmit_tasks(dir.string(), c, resubmitted);
  CHECK(resubmitted.str().find("resubmitted 2 tasks (1-2)") != std::string::npos);
  CHECK(read(dir / "job-resubmit-0.sbatch").find("#SBATCH --array=1-2\n") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "logs" / "task-1.out"));

  // A task whose own code threw says why.
  write_task_failure(dir.string(), 2, "cannot read instance-3.pddl");
  write_task_result(dir.string(), 1, nlohmann::json{{"runs", 2}});
  c = collect_tasks(dir.string(), m);
  CHECK(c.failed.at(2) == "cannot read instance-3.pddl");
  write_task_result(dir.string(), 2, nlohmann::json{{"runs", 3}});
  CHECK(collect_tasks(dir.string(), m).complete());
  fs::remove_all(dir);
}

TEST_CASE("a folder that --slurm did not write is refused by name") {
  const fs::path dir = fresh_dir("foreign");
  CHECK_THROWS_WITH(read_manifest(dir.string()), Catch::Contains("manifest.json"));
  std::ofstream(dir / "manifest.json") << "{\"kind\": 3";
  CHECK_THROWS_WITH(read_manifest(dir.string()), Catch::Contains("not a manifest"));
  fs::remove_all(dir);
}

TEST_CASE("a task whose code throws leaves its error for merge and throws on") {
  const fs::path dir = fresh_dir("throws");
  std::ostringstream out;
  submit_array(dir.string(), three_tasks(dir), out);
  CHECK_THROWS_WITH(run_array_task(dir.string(), 1, [] { throw std::runtime_error("cannot read instance-2.pddl"); }),
                    "cannot read instance-2.pddl");
  const CollectedTasks c = collect_tasks(dir.string(), read_manifest(dir.string()));
  REQUIRE(c.failed.count(1) == 1);
  CHECK(c.failed.at(1) == "cannot read instance-2.pddl");
  run_array_task(dir.string(), 0, [&] { write_task_result(dir.string(), 0, nlohmann::json::array()); });
  CHECK(collect_tasks(dir.string(), read_manifest(dir.string())).results.count(0) == 1);
  fs::remove_all(dir);
}
