// alplan bench stability --ipc DIR [--domains a,b] [--problems 1-5] [--perturbations N]
//                        [--kinds fact,object,goal] [--strategies replan,adapt,stable,patch]
//                        [--cross-check [--cross-check-seconds S]] --out DIR
// Replanning against plan repair on IPC temporal domains, after Fox et al.
// (ICAPS 2006): benchmarks/harness/stability_bench.h.
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "benchmarks/harness/stability_bench.h"
#include "benchmarks/harness/ledger_results.h"
#include "cli/commands.h"
#include "cli/test_set_flags.h"
#include "planner/search_configuration.h"
#include "repair/repair_strategy.h"

namespace alplan::cli {
namespace {

struct BenchStabilityOptions {
  bench::StabilityBenchOptions bench;
  std::string domains = "driverlog,rovers,depots,satellite,zenotravel";
  std::string problems = "1-5";
  std::string kinds = "fact,object,goal";
  std::string strategies = "replan,adapt,stable,patch";
  std::string out;
  std::string summarize;  // a run's folder: its summary again, nothing run
  double repair_seconds = 10.0;
  double min_weight = 3.0;
  std::uint64_t expansions = 1000;
  bench::TestSetRunOptions test_set;
};

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> items;
  std::istringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

// A short name (driverlog) is the IPC 2002 temporal folder Fox et al. used.
std::string domain_folder(const std::string& name) {
  static constexpr std::pair<const char*, const char*> kFolders[] = {
      {"driverlog", "ipc-2002/driverlog-time-automatic"},
      {"rovers", "ipc-2002/rovers-time-automatic"},
      {"depots", "ipc-2002/depots-time-simple-automatic"},
      {"satellite", "ipc-2002/satellite-time-simple-automatic"},
      {"zenotravel", "ipc-2002/zenotravel-time-simple-automatic"}};
  for (const auto& [short_name, folder] : kFolders) {
    if (name == short_name) return folder;
  }
  return name;
}

// Fills the bench options from the flags; an error message, or empty.
std::string resolve(BenchStabilityOptions& o) {
  o.bench.domains.clear();
  for (const std::string& d : split(o.domains)) o.bench.domains.push_back(domain_folder(d));
  const std::size_t dash = o.problems.find('-');
  try {
    o.bench.first_problem = std::stoi(o.problems.substr(0, dash));
    o.bench.last_problem = dash == std::string::npos ? o.bench.first_problem : std::stoi(o.problems.substr(dash + 1));
  } catch (const std::exception&) {
    return "--problems takes N or N-M; got '" + o.problems + "'";
  }
  if (o.bench.first_problem < 1 || o.bench.last_problem < o.bench.first_problem) {
    return "--problems takes N or N-M with 1 <= N <= M; got '" + o.problems + "'";
  }
  try {
    if (!proves_cost_optimal(parse_search_configuration(o.bench.strategy.stable_proof_search).engine)) {
      return "--stable-search must be a complete search that proves its plan minimal: "
             "complete(wastar(H, w=1, order=metric, preferred=false)) with H blind or lmcut";
    }
  } catch (const SearchConfigurationError& e) {
    return std::string("--stable-search: ") + e.what();
  }
  o.bench.kinds.clear();
  for (const std::string& k : split(o.kinds)) {
    const std::optional<bench::PerturbationKind> kind = bench::perturbation_kind(k);
    if (!kind) return "--kinds takes fact, object, goal; got '" + k + "'";
    o.bench.kinds.push_back(*kind);
  }
  o.bench.strategies = split(o.strategies);
  if (o.bench.strategies.empty() || o.bench.kinds.empty()) return "--strategies and --kinds need at least one name";
  for (const std::string& s : o.bench.strategies) {
    try {
      repair::make_strategy(s, {});
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
  }
  if (o.bench.ipc_dir.empty()) return "--ipc is required";
  if (o.out.empty()) return "--out is required";
  o.bench.strategy.planner.time_limit = o.repair_seconds;
  o.bench.strategy.planner.search = with_anytime(o.bench.strategy.planner.search, o.min_weight, o.expansions);
  return "";
}

// summary.md again from a run's runs.json: the tables re-derived from the
// committed runs, with this build's statistics.
int summarize(const BenchStabilityOptions& o) {
  try {
    bench::StabilityBenchOptions options = o.bench;
    options.strategies.clear();
    const bench::StabilityBenchResult result = bench::read_stability_runs(o.summarize + "/runs.json", options.strategies);
    if (options.strategies.empty()) throw std::runtime_error(o.summarize + "/runs.json: no runs");
    const std::string summary = bench::stability_summary(result, options);
    std::ofstream(o.summarize + "/summary.md") << summary;
    std::cout << summary << "wrote " << o.summarize << "/summary.md\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

int run_stability(BenchStabilityOptions o) {
  if (!o.summarize.empty()) return summarize(o);
  const std::string error = resolve(o);
  if (!error.empty()) {
    std::cerr << "error: " << error << "\n";
    return kExitInputError;
  }
  o.bench.progress = &std::cerr;
  try {
    std::vector<int> numbers;
    for (int n = o.bench.first_problem; n <= o.bench.last_problem; ++n) numbers.push_back(n);
    std::optional<bench::TestSetRun> ledger;
    if (const std::optional<std::string> test_set = bench::instance_test_set(numbers)) {
      ledger.emplace(bench::TestSetRunHead{*test_set, "bench stability", bench::command_line(), o.out}, o.test_set);
    }
    const bench::StabilityBenchResult result = bench::run_stability_bench(o.bench);
    bench::write_stability_results(result, o.bench, o.out);
    std::cout << bench::stability_summary(result, o.bench) << "wrote " << o.out << "/runs.csv, runs.json, summary.md\n";
    if (ledger) {
      ledger->finish(bench::stability_ledger_result(result));
      std::cerr << "recorded in the test-set ledger: " << ledger->ledger() << " (" << ledger->id() << ")\n";
    }
    if (result.runs.empty()) {
      // Every problem skipped (a wrong --ipc path reads as a missing file
      // per problem): a run that compared nothing is no result.
      std::cerr << "error: no perturbation was run: every problem or perturbation was skipped (" << o.out
                << "/summary.md, \"Skipped\", says why)\n";
      return kExitInputError;
    }
    return 0;
  } catch (const bench::TestSetRefused& e) {
    std::cerr << "error: refused: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

}  // namespace

void add_bench_stability_command(CLI::App* bench, int& exit_code) {
  auto o = std::make_shared<BenchStabilityOptions>();
  CLI::App* s = bench->add_subcommand(
      "stability", "Replanning against plan repair on IPC temporal domains, perturbed while the plan runs");
  s->add_option("--ipc", o->bench.ipc_dir, "The IPC folder (shared/benchmarks/ipc; required)");
  s->add_option("--domains", o->domains,
                "Comma-separated: driverlog, rovers, depots, satellite, zenotravel (IPC 2002 temporal), or folders "
                "under --ipc");
  s->add_option("--problems", o->problems, "Instances N or N-M (1-5 to tune, 6-10 to test)");
  s->add_option("--perturbations", o->bench.perturbations, "Perturbations per problem and kind")
      ->check(CLI::PositiveNumber);
  s->add_option("--kinds", o->kinds, "Comma-separated: fact, object, goal");
  s->add_option("--strategies", o->strategies, "Comma-separated repair strategies; the first is the reference");
  s->add_option("--seed", o->bench.seed, "Seed of the perturbations");
  s->add_option("--plan-time", o->bench.plan_seconds, "Seconds for each problem's first plan")
      ->check(CLI::PositiveNumber);
  s->add_option("--repair-time", o->repair_seconds, "Seconds per repair's planner call")->check(CLI::PositiveNumber);
  s->add_option("--repair-expansions", o->expansions, "Expansions each anytime weight of a repair may spend");
  s->add_option("--adapt-budget", o->bench.strategy.adapt_budget, "adapt: seconds of anytime search")
      ->check(CLI::PositiveNumber);
  s->add_option("--stable-search", o->bench.strategy.stable_proof_search,
                "stable: the complete search on the distance that proves its repair minimal (default "
                "complete(wastar(lmcut, w=1, order=metric, preferred=false)), A*; blind for uniform-cost search)");
  s->add_flag("--cross-check", o->bench.cross_check,
              "Per perturbation, compute stable's minimum distance again from a classical compilation solved with "
              "A* on LM-cut (benchmarks/harness/stable_cross_check.h)");
  s->add_option("--cross-check-seconds", o->bench.cross_check_seconds, "Seconds per cross-check's search")
      ->check(CLI::PositiveNumber);
  s->add_option("--out", o->out, "Folder for runs.csv, runs.json, summary.md (required)");
  add_test_set_flags(s, o->test_set);
  s->add_option("--summarize", o->summarize, "Write a run folder's summary.md again from its runs.json; runs nothing");
  s->callback([o, &exit_code] { exit_code = run_stability(*o); });
}

}  // namespace alplan::cli
