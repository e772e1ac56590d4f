// alplan bench grounding|...: the benchmark harness, one process per run.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <iostream>
#include <memory>
#include <sstream>

#include "benchmarks/harness/grounding_bench.h"
#include "benchmarks/harness/planner_bench.h"
#include "benchmarks/harness/process_runner.h"
#include "cli/commands.h"
#include "cli/slurm_options.h"
#include "cli/test_set_flags.h"

namespace alplan::cli {
namespace {

struct BenchGroundingOptions {
  std::string suite;
  std::string out;
  double time_limit = 60;
  double memory_limit = 4096;
  bool all = false;
};

int run_grounding(const BenchGroundingOptions& options) {
  bench::GroundingBenchOptions o;
  o.suite = options.suite;
  o.out_dir = options.out;
  o.alplan = bench::self_executable();
  o.limits = {options.time_limit, options.memory_limit};
  o.largest_only = !options.all;
  try {
    return bench::run_grounding_bench(o, std::cout, std::cerr) == 0 ? kExitOk : kExitInvalid;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

struct BenchPlannersOptions {
  std::string suite;
  std::string out;
  std::string baseline;
  std::vector<std::string> references;
  double time_limit = 60;
  double memory_limit = 4096;
  int jobs = 1;
  int first = 0;
  std::string instances;  // "A-B": positions A to B of each domain
  std::vector<std::string> domains;  // name prefixes
  bool anytime = false;
  std::string search = "ehc";
  std::string order;  // "": the planner's default
  std::vector<std::string> plan_args;
  std::vector<std::string> planners;  // NAME=COMMAND, other planners beside ours
  SlurmFlags slurm;
  bench::TestSetRunOptions test_set;
};

int run_planners(const BenchPlannersOptions& options) {
  bench::PlannerBenchOptions o;
  o.suite = options.suite;
  o.out_dir = options.out;
  o.alplan = bench::self_executable();
  o.baseline = options.baseline;
  o.references = options.references;
  o.limits = {options.time_limit, options.memory_limit};
  o.jobs = options.jobs;
  o.progress_bar = isatty(STDERR_FILENO) != 0;
  o.first = options.first;
  if (!options.instances.empty()) {
    int from = 0, to = 0;
    char dash = 0;
    std::istringstream range(options.instances);
    if (!(range >> from >> dash >> to) || dash != '-' || from < 1 || to < from || !range.eof()) {
      std::cerr << "error: --instances " << options.instances << ": expected A-B with 1 <= A <= B (e.g. 6-10)\n";
      return kExitInputError;
    }
    o.from = from;
    o.to = to;
  }
  o.domains = options.domains;
  o.anytime = options.anytime;
  o.search = options.search;
  o.order = options.order;
  o.plan_args = options.plan_args;
  o.test_set = options.test_set;
  try {
    for (const std::string& spec : options.planners) o.external.push_back(bench::parse_external_planner(spec));
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
  std::string error;
  if (!array_run(options.slurm, options.out, o.array, error)) {
    std::cerr << "error: " << error << "\n";
    return kExitInputError;
  }
  try {
    return bench::run_planner_bench(o, std::cout, std::cerr) == 0 ? kExitOk : kExitInvalid;
  } catch (const bench::TestSetRefused& e) {
    std::cerr << "error: refused: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

}  // namespace

void add_bench_command(CLI::App& app, int& exit_code) {
  CLI::App* bench = app.add_subcommand("bench", "Benchmark harness: runs in separate processes under limits");
  bench->require_subcommand(1);

  auto grounding = std::make_shared<BenchGroundingOptions>();
  CLI::App* g = bench->add_subcommand("grounding", "Ground the largest problem of every domain; time and memory");
  g->add_option("--suite", grounding->suite, "Suite folder (like shared/benchmarks/ipc) or list file")->required();
  g->add_option("--out", grounding->out, "Folder for grounding.csv, .json and .md");
  g->add_option("--time-limit", grounding->time_limit, "Seconds per problem")->check(CLI::PositiveNumber);
  g->add_option("--memory-limit", grounding->memory_limit, "MiB of address space per problem")
      ->check(CLI::PositiveNumber);
  g->add_flag("--all", grounding->all, "Every problem, not only the largest of each domain");
  g->callback([grounding, &exit_code] { exit_code = run_grounding(*grounding); });

  auto planners = std::make_shared<BenchPlannersOptions>();
  CLI::App* p = bench->add_subcommand("planners", "Run our planner (and others by --planner) on a suite, validate, compare with a baseline");
  p->add_option("--suite", planners->suite, "Suite folder, list file, or baseline CSV")->required();
  p->add_option("--out", planners->out, "Folder for runs.csv, runs.json, summary.md and the plans");
  p->add_option("--baseline", planners->baseline,
                "Folder with optic_popf_60s.csv and quality_ref.csv, or (PDDL 3) optic_60s.csv");
  p->add_option("--reference", planners->references,
                "A CSV of reference values per problem (a problem_file column, numeric columns), scored beside "
                "ours in quality.md (repeat it); the baseline's quality_ref.csv is read without it")
      ->check(CLI::ExistingFile);
  p->add_option("--time-limit", planners->time_limit, "Seconds per run")->check(CLI::PositiveNumber);
  p->add_option("--memory-limit", planners->memory_limit, "MiB per run")->check(CLI::PositiveNumber);
  p->add_option("--jobs", planners->jobs, "Runs at once (1 for timings comparable to the baseline)")
      ->check(CLI::PositiveNumber);
  p->add_option("--first", planners->first, "Only the first N problems of each domain");
  p->add_option("--instances", planners->instances,
                 "Only problems A to B of each domain, e.g. 6-10 (a test set beside the first five)");
  p->add_option("--domains", planners->domains,
                 "Only the domains whose name begins with one of these (e.g. ipc-2006/ for the temporal PDDL 3 tracks)")
      ->delimiter(',');
  p->add_flag("--anytime", planners->anytime, "Let each run improve its plan until the time limit");
  p->add_option("--search", planners->search,
                 "The search configuration of every run: ehc (the default), gbfs, wastar, an alias or an expression "
                 "(alplan plan --search)");
  p->add_option("--order", planners->order, "How wastar orders nodes: metric or steps")
      ->check(CLI::IsMember({"metric", "steps"}));
  p->add_option("--plan-arg", planners->plan_args,
                "A flag for every alplan plan run, as given (repeat it; e.g. --plan-arg=--deferred)")
      ->allow_extra_args(false);
  p->add_option("--planner", planners->planners,
                "Another planner beside ours, as NAME='COMMAND {domain} {problem} {plan}' (repeat it): run under "
                "/bin/sh with the same limits, its plan written to {plan} and judged by our validator")
      ->allow_extra_args(false);
  add_slurm_options(p, planners->slurm);
  add_test_set_flags(p, planners->test_set);
  p->callback([planners, &exit_code] { exit_code = run_planners(*planners); });

#ifndef ALPLAN_PLANNER_ONLY
  add_bench_repair_command(bench, exit_code);
  add_bench_stability_command(bench, exit_code);
#endif
  add_bench_merge_command(bench, exit_code);
}

}  // namespace alplan::cli
