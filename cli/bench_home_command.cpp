// alplan bench home [--seniors N] [--robots N] [--rooms N] [--objects N]
//                   [--hours H] [--seed S] [--planner-expansions N] [--out DIR]
// The running home at scale (home/home_bench.h): a generated home run for
// simulated hours with seniors stressed at random; prints the planning
// latency by reason and the share comforted within their windows as a
// Markdown table, and writes DIR/bench-home.json.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "cli/commands.h"
#include "cli/home_run_options.h"
#include "cli/perceive_common.h"
#include "cli/perception_module.h"
#include "cli/test_set_flags.h"
#include "home/home_bench.h"
#include "planner/progress_meter.h"
#include "repair/repair_strategy.h"

namespace alplan::cli {
namespace {

struct BenchHomeOptions {
  home::HomeSettings settings;
  double hours = 8.0;
  std::string out;
  bench::TestSetRunOptions test_set;  // where the home is held out (test_set_ledger.h)
};

// What the ledger keeps of a run on a held-out home: the figures its
// table leads with (the rest is in bench-home.json).
nlohmann::json ledger_result(const nlohmann::json& result) {
  nlohmann::json kept = nlohmann::json::object();
  for (const char* key : {"comforted_within_window_share", "never_served", "meetable_goals", "weighted_lateness_s"}) {
    if (result.contains(key)) kept[key] = result[key];
  }
  return kept;
}

int run_bench_home(BenchHomeOptions& o) {
  std::optional<bench::TestSetRun> ledger;
  if (const std::optional<std::string> test_set = bench::home_test_set(o.settings.seed, 1)) {
    try {
      ledger.emplace(bench::TestSetRunHead{*test_set, "bench home", bench::command_line(), o.out}, o.test_set);
    } catch (const bench::TestSetRefused& e) {
      std::cerr << "error: refused: " << e.what() << "\n";
      return kExitInputError;
    }
  }
  o.settings.until = o.hours * 3600.0;
  ProgressMeter meter(std::cerr, o.settings.until, "simulated s", isatty(STDERR_FILENO) != 0);
  const home::HomeBenchResult result = home::run_home_bench(o.settings, simulated_time_meter(meter));
  meter.finish();
  home::print_home_bench(std::cout, o.settings, result);
  if (!o.out.empty()) {
    std::filesystem::create_directories(o.out);
    const std::string path = o.out + "/bench-home.json";
    std::ofstream(path) << result.json(o.settings).dump(2) << "\n";
    std::cout << "wrote " << path << "\n";
  }
  if (ledger) {
    ledger->finish(ledger_result(result.json(o.settings)));
    std::cerr << "recorded in the test-set ledger: " << ledger->ledger() << " (" << ledger->id() << ")\n";
  }
  return kExitOk;
}

}  // namespace

void add_bench_home_command(CLI::App* bench, int& exit_code) {
  auto o = std::make_shared<BenchHomeOptions>();
  home::HomeSettings& s = o->settings;
  s.domains_dir = ALPLAN_ASSISTED_LIVING_DIR;
  s.generate_seniors = 40;
  s.generate_robots = 4;
  s.generate_rooms = 50;
  s.generate_objects = 400;
  s.score_meetable = true;
  CLI::App* cmd = bench->add_subcommand("home", kBenchHomeHelp);
  cmd->add_option("--seniors", s.generate_seniors, "Seniors of the generated home")->check(CLI::Range(1, 1000));
  cmd->add_option("--robots", s.generate_robots, "Robots")->check(CLI::Range(1, 100));
  cmd->add_option("--rooms", s.generate_rooms, "Rooms besides corridors")->check(CLI::Range(4, 1000));
  cmd->add_option("--objects", s.generate_objects, "Portable objects")->check(CLI::Range(1, 10000));
  cmd->add_option("--hours", o->hours, "Simulated hours")->check(CLI::Range(0.01, 168.0));
  cmd->add_option("--seed", s.seed, "Seed of the home, the seniors and the failures");
  add_home_run_options(*cmd, s);
  cmd->add_option("--strategy", s.strategy, "Repair strategy: " + repair::strategy_list());
  cmd->add_option("--out", o->out, "Write bench-home.json here");
  add_test_set_flags(cmd, o->test_set);
  cmd->add_option("--unplanned-dir", s.unplanned_dir, "Write each problem the planner found no plan for here (PDDL)");
  cmd->add_flag("!--no-score-meetable", s.score_meetable,
                "Skip asking, for each goal, whether one idle robot could have met its window alone");
  cmd->callback([o, &exit_code] { exit_code = guarded([&] { return run_bench_home(*o); }, "bench home"); });
}

}  // namespace alplan::cli
