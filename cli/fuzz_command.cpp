// alplan fuzz planner: the differential tester (benchmarks/differential/).
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "benchmarks/differential/differential.h"
#include "cli/commands.h"

namespace alplan::cli {

void add_fuzz_command(CLI::App& app, int& exit_code) {
  CLI::App* fuzz = app.add_subcommand("fuzz", "Differential testing against a brute force over the reference semantics");
  fuzz->require_subcommand(1);
  auto options = std::make_shared<differential::DifferentialOptions>();
  CLI::App* p = fuzz->add_subcommand(
      "planner",
      "Random small temporal tasks: the planner against a brute-force search judged by the reference semantics "
      "(oracle/), which shares no code with the planner; exit 0 with no disagreement, 1 with one");
  p->add_option("--tasks", options->tasks, "How many tasks (default 100)");
  p->add_option("--seed", options->seed,
                "The run's seed (default 1): task k is generated from seed * 2^32 + k, so runs with different "
                "seeds check disjoint tasks");
  p->add_option_function<std::uint64_t>(
      "--task-seed", [options](const std::uint64_t& seed) { options->task_seed = seed; },
      "Check only the task generated from this seed (the number a disagreement prints)");
  p->add_option("--seconds", options->seconds, "Stop after this many seconds even if tasks remain")
      ->check(CLI::PositiveNumber);
  p->add_option("--time-limit", options->planner_time_limit, "The planner's seconds per task")
      ->check(CLI::PositiveNumber);
  p->add_option("--node-limit", options->planner_node_limit, "The planner's search nodes per task")
      ->check(CLI::PositiveNumber);
  p->add_option("--retry-time-limit", options->retry_time_limit,
                "Where the brute force finds a plan and the planner reached its limit, the planner's seconds for a "
                "second run before the plan is called missed (default 60; at most --time-limit: no second run)")
      ->check(CLI::PositiveNumber);
  p->add_option("--max-steps", options->brute_force.max_steps, "The brute force's longest plan (default 3)")
      ->check(CLI::Range(1, 6));
  p->add_option("--max-judgements", options->brute_force.max_judgements,
                "Plans the brute force may judge per task before it is cut short (undecided)")
      ->check(CLI::PositiveNumber);
  p->add_option("--jobs", options->jobs, "Tasks checked at once (threads); the report is the same for any number")
      ->check(CLI::Range(1, 64));
  p->add_option("--write-tasks", options->all_dir, "Folder to write every task into, with the class it fell in and the planner's and the brute force's plans");
  p->add_flag("!--no-shrink", options->shrink, "Write disagreeing tasks as found, without reducing them");
  p->add_option("--out", options->out_dir, "Folder to write each disagreeing task into (domain, problem, plan)");
  auto json_path = std::make_shared<std::string>();
  p->add_option("--json", *json_path, "Also write the report as JSON to this file (benchmarks/readme_figures.py reads it)");
  p->callback([options, json_path, &exit_code] {
    const differential::DifferentialReport report = differential::run_differential(*options, std::cerr);
    differential::print_report(report, std::cout);
    if (!json_path->empty()) {
      std::ofstream json(*json_path);
      differential::write_report_json(report, json);
      if (!json) {
        std::cerr << "error: cannot write " << *json_path << "\n";
        exit_code = kExitInputError;
        return;
      }
    }
    exit_code = report.disagreements.empty() ? kExitOk : kExitInvalid;
  });
}

}  // namespace alplan::cli
