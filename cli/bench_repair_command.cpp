// alplan bench repair --homes N --failures-per-run K --seed S
//                     --strategies replan,substitute,suggest,patch,adapt,switch --out DIR
//                     [--runs-per-home R] [--external] [--events KINDS] [--observe full|iot|camera] [--rooms ...]
// Compares repair strategies on the same failures in generated homes: a
// paired study per failure kind (benchmarks/harness/repair_study.h).
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>

#include "benchmarks/harness/ledger_results.h"
#include "benchmarks/harness/observation_study.h"
#include "benchmarks/harness/repair_study_folder.h"
#include "benchmarks/harness/process_runner.h"
#include "benchmarks/harness/repair_bench.h"
#include "cli/commands.h"
#include "cli/perception_module.h"
#include "cli/slurm_options.h"
#include "cli/test_set_flags.h"
#include "domains/pddl_files.h"
#include "repair/observation.h"
#include "repair/random_events.h"
#include "repair/repair_strategy.h"

namespace alplan::cli {
namespace {

struct BenchRepairOptions {
  bench::RepairBenchOptions bench;
  std::string strategies = "replan,substitute,suggest,patch,adapt,switch";
  std::string events = "arrival,iot,sibling,moves,emotion,overrun,two";
  std::string observe = "iot";
  std::string recognizer = "cnn";
  std::string summarize;  // a run's folder: its summaries again from its runs, nothing run
  SlurmFlags slurm;
  bench::TestSetRunOptions test_set;  // where the homes are held out (test_set_ledger.h)
};

// "all", or a comma-separated list of random event kinds.
std::optional<std::vector<repair::RandomEventKind>> event_kinds(const std::string& list) {
  if (list == "all") return repair::all_random_event_kinds();
  std::vector<repair::RandomEventKind> kinds;
  std::istringstream in(list);
  for (std::string name; std::getline(in, name, ',');) {
    if (name.empty()) continue;
    const std::optional<repair::RandomEventKind> kind = repair::random_event_kind(name);
    if (!kind) return std::nullopt;
    kinds.push_back(*kind);
  }
  if (kinds.empty()) return std::nullopt;
  return kinds;
}

// The same study under each observation model, each in its own folder
// (out/full, out/iot, ...), then what the sensors change (observation.md).
int run_under_models(const bench::RepairBenchOptions& base, const std::vector<repair::ObservationModel>& models) {
  std::map<std::string, std::vector<bench::StudyRun>> by_model;
  for (repair::ObservationModel model : models) {
    bench::RepairBenchOptions o = base;
    o.observation.model = model;
    o.out_dir = base.out_dir + "/" + repair::to_string(model);
    if (const int code = bench::run_repair_bench(o, std::cout, std::cerr); code != 0) return code;
    by_model[repair::to_string(model)] = bench::load_study_runs(o.out_dir + "/runs.json");
  }
  const std::string tables = bench::observation_tables(by_model, base.strategies, base.bootstrap);
  std::ofstream(base.out_dir + "/observation.md") << tables;
  std::cout << tables << "wrote " << base.out_dir << "/observation.md\n";
  return 0;
}

// observation.md again from DIR/full, DIR/iot and DIR/camera's runs.json
// (those present), the strategies in the order the runs name them.
int summarize_models(const BenchRepairOptions& o) {
  std::map<std::string, std::vector<bench::StudyRun>> by_model;
  std::vector<std::string> strategies;
  for (const char* model : {"full", "iot", "camera"}) {
    const std::string runs = o.summarize + "/" + model + "/runs.json";
    if (!std::ifstream(runs)) continue;
    try {
      by_model[model] = bench::load_study_runs(runs);
    } catch (const std::exception& e) {
      std::cerr << "error: " << runs << ": " << e.what() << "\n";
      return kExitInputError;
    }
    for (const bench::StudyRun& r : by_model[model]) {
      if (std::find(strategies.begin(), strategies.end(), r.strategy) == strategies.end()) strategies.push_back(r.strategy);
    }
  }
  if (by_model.empty()) {
    std::cerr << "error: --summarize " << o.summarize << ": no full/, iot/ or camera/ runs.json in it\n";
    return kExitInputError;
  }
  for (const auto& [model, runs] : by_model) {
    try {
      bench::summarise_study_folder(o.summarize + "/" + model, o.bench.bootstrap);
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      return kExitInputError;
    }
    std::cout << "wrote " << o.summarize << "/" << model << "/summary.md, summary.json and plots/\n";
  }
  if (by_model.size() < 2) return 0;  // observation.md compares two models or more
  const std::string tables = bench::observation_tables(by_model, strategies, o.bench.bootstrap);
  std::ofstream out(o.summarize + "/observation.md");
  out << tables;
  if (!out) {
    std::cerr << "error: cannot write " << o.summarize << "/observation.md\n";
    return kExitInputError;
  }
  std::cout << tables << "wrote " << o.summarize << "/observation.md\n";
  return 0;
}

// What the ledger keeps of a run on held-out homes (ledger_results.h), read
// from the runs.json files the study wrote.
nlohmann::json ledger_result(const bench::RepairBenchOptions& o, const std::vector<repair::ObservationModel>& models) {
  std::map<std::string, std::vector<bench::StudyRun>> by_model;
  for (repair::ObservationModel model : models) {
    const std::string folder = models.size() > 1 ? o.out_dir + "/" + repair::to_string(model) : o.out_dir;
    by_model[repair::to_string(model)] = bench::load_study_runs(folder + "/runs.json");
  }
  return bench::repair_ledger_result(by_model);
}

// The study, recorded in the test-set ledger where its homes are held out:
// a local run when it ends, an array when it is submitted (its tasks and
// merge must then run the submitted binary).
int run_recorded(const BenchRepairOptions& options, const std::vector<repair::ObservationModel>& models) {
  const bench::RepairBenchOptions& o = options.bench;
  const std::optional<std::string> test_set = bench::home_test_set(o.seed, static_cast<std::uint64_t>(o.homes));
  std::optional<bench::TestSetRun> ledger;
  if (test_set && (o.array.role == bench::ArrayRole::local || o.array.role == bench::ArrayRole::submit)) {
    ledger.emplace(bench::TestSetRunHead{*test_set, "bench repair", bench::command_line(), o.out_dir}, options.test_set);
  } else if (test_set) {
    bench::check_array_build(o.out_dir, options.test_set);
  }
  const int code = models.size() > 1 ? run_under_models(o, models) : bench::run_repair_bench(o, std::cout, std::cerr);
  if (ledger && code == 0) {
    ledger->finish(o.array.role == bench::ArrayRole::submit
                       ? nlohmann::json{{"submitted", "a Slurm array: its result is what its merge prints"}}
                       : ledger_result(o, models));
    std::cerr << "recorded in the test-set ledger: " << ledger->ledger() << " (" << ledger->id() << ")\n";
  }
  return code;
}

int run_repair(BenchRepairOptions options) {
  if (!options.summarize.empty()) {
    try {
      return summarize_models(options);
    } catch (const std::exception& e) {
      std::cerr << "error: --summarize " << options.summarize << ": " << e.what() << "\n";
      return kExitInputError;
    }
  }
  options.bench.progress_bar = isatty(STDERR_FILENO) != 0;
  options.bench.strategies.clear();
  std::istringstream list(options.strategies);
  for (std::string name; std::getline(list, name, ',');) {
    if (name.empty()) continue;
    try {
      repair::make_strategy(name, {});
    } catch (const std::invalid_argument& e) {
      std::cerr << "error: " << e.what() << "\n";
      return kExitInputError;
    }
    options.bench.strategies.push_back(name);
  }
  const auto kinds = event_kinds(options.events);
  if (!kinds) {
    std::cerr << "error: --events takes 'all' or a list of arrival, iot, sibling, moves, emotion, overrun, two, "
                 "unavailable, appears; got '"
              << options.events << "'\n";
    return kExitInputError;
  }
  options.bench.events.kinds = *kinds;
  std::vector<repair::ObservationModel> models;
  std::istringstream model_list(options.observe);
  for (std::string name; std::getline(model_list, name, ',');) {
    const std::optional<repair::ObservationModel> model = repair::observation_model(name);
    if (!model) {
      std::cerr << "error: --observe takes full, iot or camera, or a list of them; got '" << options.observe << "'\n";
      return kExitInputError;
    }
    models.push_back(*model);
  }
  if (models.empty()) {
    std::cerr << "error: --observe takes full, iot or camera, or a list of them; got '" << options.observe << "'\n";
    return kExitInputError;
  }
  options.bench.observation.model = models.front();
  if (options.bench.out_dir.empty()) {
    std::cerr << "error: --out is required\n";
    return kExitInputError;
  }
  std::string error;
  if (!array_run(options.slurm, options.bench.out_dir, options.bench.array, error)) {
    std::cerr << "error: " << error << "\n";
    return kExitInputError;
  }
  // Submitting and merging run nothing: the tasks train their own camera.
  const bool runs = options.bench.array.role == bench::ArrayRole::local || options.bench.array.role == bench::ArrayRole::task;
  if (options.recognizer == "cnn" && runs) {
    if (!load_drawing_camera(options.bench.assisted_living_dir + "/types.ttl", options.bench.camera,
                             options.bench.camera_info, error)) {
      std::cerr << "error: --recognizer cnn: " << error << "\n";
      return kExitInputError;
    }
  } else if (options.recognizer != "simulated") {
    std::cerr << "error: --recognizer takes cnn or simulated; got '" << options.recognizer << "'\n";
    return kExitInputError;
  }
  options.bench.alplan = bench::self_executable();
  try {
    return run_recorded(options, models);
  } catch (const bench::TestSetRefused& e) {
    std::cerr << "error: refused: " << e.what() << "\n";
    return kExitInputError;
  } catch (const domains::InputError& e) {
    std::cerr << e.what();
    return kExitInputError;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

}  // namespace

void add_bench_repair_command(CLI::App* bench, int& exit_code) {
  auto o = std::make_shared<BenchRepairOptions>();
  o->bench.assisted_living_dir = ALPLAN_ASSISTED_LIVING_DIR;
  CLI::App* r = bench->add_subcommand("repair", "Compare repair strategies on the same failures in generated homes");
  r->add_option("--homes", o->bench.homes, "Generated homes")->check(CLI::PositiveNumber);
  r->add_option("--failures-per-run", o->bench.failures_per_run, "Failures injected into each execution")
      ->check(CLI::PositiveNumber);
  r->add_option("--runs-per-home", o->bench.runs_per_home, "Executions per home, each with its own failures")
      ->check(CLI::PositiveNumber);
  r->add_option("--seed", o->bench.seed, "First home's seed; the others follow");
  r->add_option("--strategies", o->strategies, "Comma-separated: replan, substitute, suggest, patch, adapt, switch");
  r->add_option("--events", o->events,
                "Failures to draw: 'all' or a comma-separated list of arrival, iot, sibling, moves, emotion, overrun, "
                "two (the study's, the default), unavailable, appears");
  r->add_option("--observe", o->observe,
                "What the monitor sees: full (the true state), iot (IoT tags, wristbands, the robot's camera; the "
                "paper's), camera (the robot's camera only); a list (full,iot,camera) runs the study under each, "
                "in out/MODEL/, and compares them in out/observation.md");
  r->add_flag("!--no-search", o->bench.observation.search_lost_persons,
              "A senior the robot finds gone (camera) is believed nowhere, instead of searched for nearest place "
              "first (repair/person_search.h)");
  r->add_option("--recognizer", o->recognizer,
                "What names the new things the camera sees: cnn (the paper's CNN on drawings of them, trained when "
                "the run starts; its time is part of substitute's latency) or simulated (the simulator, perfect, free)");
  r->add_flag("!--first-plan", o->bench.repair_anytime,
              "Repairs take the first plan found (as the external planner does) instead of a short anytime search");
  r->add_option("--repair-expansions", o->bench.repair_expansions,
                "Expansions each anytime weight of a repair may spend (0: until proven)");
  r->add_option("--repair-min-weight", o->bench.repair_min_weight,
                "The lowest weight of the repairs' anytime search (5, 3, 2, 1.5, 1 down to this; default 3)")
      ->check(CLI::PositiveNumber);
  r->add_option("--iot-share", o->bench.home.iot_share, "Share of the generated homes' objects with an IoT tag");
  r->add_option("--scatter", o->bench.home.scatter,
                "Share of the generated homes' objects left in another room than their type's (default 0)");
  r->add_option("--bootstrap", o->bench.bootstrap.resamples, "Bootstrap resamples for the confidence intervals")
      ->check(CLI::PositiveNumber);
  r->add_flag("!--no-paper-home", o->bench.paper_home, "Skip timing the strategies on the paper's three scenarios");
  r->add_option("--out", o->bench.out_dir, "Folder for runs.csv, runs.json, summary.md, summary.json, plots/ (required)");
  r->add_option("--summarize", o->summarize,
                "Summarise a run folder again from its full/, iot/, camera/ runs.json: each model's summary.md "
                "tables, summary.json and plots/, and observation.md where there are two models or more; runs "
                "nothing");
  r->add_flag("!--no-grounding-reuse", o->bench.reuse_grounding,
              "Ground every repair's problem from scratch instead of reusing the grounding made when execution starts");
  r->add_option("--adapt-expansions", o->bench.strategy_options.adapt_expansions,
                "adapt: expansions each anytime weight may spend looking for a closer plan (0: until proven)");
  r->add_option("--adapt-min-weight", o->bench.strategy_options.adapt_min_weight,
                "adapt: the lowest weight of its anytime search (5, 3, 2, 1.5, 1 down to this)")
      ->check(CLI::PositiveNumber);
  r->add_option("--switch-plans", o->bench.strategy_options.switch_plans,
                "switch: diverse plans it keeps per goal")
      ->check(CLI::PositiveNumber);
  r->add_option("--switch-min-distance", o->bench.strategy_options.switch_min_distance,
                "switch: the fewest actions (added + removed) by which any two of them differ");
  r->add_flag("--external", o->bench.external, "Also replan through `alplan plan` in a child process (the paper's way)");
  r->add_option("--rooms", o->bench.home.rooms, "Rooms per home");
  r->add_option("--seniors", o->bench.home.seniors, "Seniors per home");
  r->add_option("--objects", o->bench.home.objects, "Portable objects per home");
  r->add_option("--stressed", o->bench.home.stressed, "Seniors to comfort per home");
  r->add_option("--domains-dir", o->bench.assisted_living_dir, "Folder with domain.pddl and types.ttl");
  r->add_option("--epsilon", o->bench.epsilon, "Separation of dependent happenings")->check(CLI::PositiveNumber);
  r->add_option("--planning-time", o->bench.planning_time, "Seconds per planner call")->check(CLI::PositiveNumber);
  r->add_option("--initial-time", o->bench.initial_planning_time, "Seconds of anytime search for each home's first plan")
      ->check(CLI::PositiveNumber);
  r->add_option("--initial-expansions", o->bench.initial_expansions,
                "Cap each weight of that search at so many expansions (0: by time alone; set, the first plans do "
                "not depend on the machine's speed)");
  add_test_set_flags(r, o->test_set);
  add_slurm_options(r, o->slurm);
  r->callback([o, &exit_code] { exit_code = run_repair(*o); });
}

}  // namespace alplan::cli
