// alplan fuzz planner: the differential tester (benchmarks/differential/).
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

#include "benchmarks/differential/differential.h"
#include "cli/commands.h"

namespace alplan::cli {

void add_fuzz_command(CLI::App& app, int& exit_code) {
  CLI::App* fuzz = app.add_subcommand("fuzz", "Differential testing against brute force");
  fuzz->require_subcommand(1);
  auto options = std::make_shared<differential::DifferentialOptions>();
  CLI::App* p = fuzz->add_subcommand(
      "planner", "Random small temporal tasks: the planner against a brute-force search through the validator");
  p->add_option("--tasks", options->tasks, "How many tasks (task k is generated from seed + k)");
  p->add_option("--seed", options->seed, "The first task's seed");
  p->add_option("--seconds", options->seconds, "Stop after this many seconds even if tasks remain")
      ->check(CLI::PositiveNumber);
  p->add_option("--time-limit", options->planner_time_limit, "The planner's seconds per task")
      ->check(CLI::PositiveNumber);
  p->add_option("--node-limit", options->planner_node_limit, "The planner's search nodes per task")
      ->check(CLI::PositiveNumber);
  p->add_option("--max-steps", options->brute_force.max_steps, "The brute force's longest plan")
      ->check(CLI::Range(1, 6));
  p->add_option("--out", options->out_dir, "Folder to write each disagreeing task into (domain, problem, plan)");
  p->callback([options, &exit_code] {
    const differential::DifferentialReport report = differential::run_differential(*options, std::cerr);
    differential::print_report(report, std::cout);
    exit_code = report.disagreements.empty() ? kExitOk : kExitInvalid;
  });
}

}  // namespace alplan::cli
