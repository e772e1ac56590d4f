// alplan scenario paper-1|paper-2|paper-3 [--strategy S] [--observe full|iot|camera] [--json]
// Runs one of the paper's scenarios end to end and prints the plans in the
// paper's format (a1 : 0.000 : (move ...)), the failure, the repair and its
// explanation. Exit 0 when the senior is comforted, 1 when the run ends with
// an explained failure, 2 on bad input.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <optional>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/paper_format.h"
#include "domains/paper_scenarios.h"
#include "domains/pddl_files.h"
#include "repair/type_ontology.h"
#include "repair/repair_strategy.h"

namespace alplan::cli {
namespace {

struct ScenarioCommandOptions {
  std::string name;
  std::string strategy = "substitute";
  std::string dir = ALPLAN_ASSISTED_LIVING_DIR;
  double epsilon = 0.002;
  double step = 5.0;
  bool no_lookahead = false;
  bool proactive = false;
  bool json = false;
  std::string observe = "iot";
};

int run(const ScenarioCommandOptions& o) {
  const std::vector<domains::PaperScenario> all = domains::paper_scenarios();
  const domains::PaperScenario* scenario = nullptr;
  for (const domains::PaperScenario& s : all) {
    if (s.name == o.name) scenario = &s;
  }
  if (!scenario) {
    std::cerr << "error: unknown scenario '" << o.name << "' (known: paper-1, paper-2, paper-3)\n";
    return kExitInputError;
  }
  const std::optional<repair::ObservationModel> model = repair::observation_model(o.observe);
  if (!model) {
    std::cerr << "error: --observe takes full, iot or camera; got '" << o.observe << "'\n";
    return kExitInputError;
  }
  domains::ScenarioOptions options;
  options.monitor.observation.model = *model;
  options.assisted_living_dir = o.dir;
  options.strategy = o.strategy;
  options.epsilon = o.epsilon;
  options.monitor.step_size = o.step;
  options.monitor.lookahead = !o.no_lookahead;
  options.monitor.proactive = o.proactive;
  domains::ScenarioRun run;
  try {
    run = domains::run_paper_scenario(*scenario, options);
  } catch (const domains::InputError& e) {
    std::cerr << e.what();
    return kExitInputError;
  } catch (const repair::OntologyError& e) {
    std::cerr << e.what() << "\n";
    return kExitInputError;
  } catch (const std::invalid_argument& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  } catch (const std::runtime_error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInvalid;
  }
  const repair::ExecutionReport& report = run.report;
  if (o.json) {
    nlohmann::json j = report.json();
    j["scenario"] = scenario->name;
    j["initial_planning_seconds"] = run.initial_planning_seconds;
    j["exogenous_events"] = run.applied_events;
    std::cout << j.dump(2) << "\n";
  } else {
    std::cout << "Scenario " << scenario->name << ": " << scenario->motivation << ".\n\n"
              << "Initial plan (the paper's " << scenario->initial_figure << "):\n"
              << paper_format(run.initial_plan) << "\n";
    for (const std::string& e : report.events) std::cout << "  " << e << "\n";
    for (const repair::RepairRecord& r : report.repairs) {
      if (!r.repaired) {
        std::cout << (r.deferred ? "\nNo repair yet (" : "\nFailed repair (") << r.strategy << "):\n" << r.explanation.text();
        continue;
      }
      std::cout << "\nRepaired plan (" << r.strategy << (r.strategy == "proactive" ? "" : ", the paper's " + scenario->repaired_figure) << "):\n"
                << paper_format(r.plan_text) << "\n" << r.explanation.text();
    }
    std::cout << "\nOutcome: " << report.outcome << "\n";
  }
  return report.goal_reached ? kExitOk : kExitInvalid;
}

}  // namespace

void add_scenario_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<ScenarioCommandOptions>();
  CLI::App* cmd = app.add_subcommand("scenario", "Run one of the paper's scenarios end to end");
  cmd->add_option("SCENARIO", options->name, "paper-1, paper-2 or paper-3")->required();
  cmd->add_option("--strategy", options->strategy, "Repair strategy: " + repair::strategy_list());
  cmd->add_option("--domains-dir", options->dir, "Folder with domain.pddl, types.ttl and the scenario problems");
  cmd->add_option("--epsilon", options->epsilon, "Separation of dependent happenings (the paper's plans: 0.002)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--step", options->step, "Seconds between observations")->check(CLI::PositiveNumber);
  cmd->add_flag("--no-lookahead", options->no_lookahead, "Check conditions only when they are due");
  cmd->add_flag("--proactive", options->proactive, "Plan again whenever perception sees new objects; switch if better");
  cmd->add_flag("--json", options->json, "Print the run as JSON");
  cmd->add_option("--observe", options->observe,
                  "What the monitor sees: iot (IoT tags, wristbands, the robot's camera; the paper's), full (the "
                  "true state), camera (the robot's camera only)");
  cmd->callback([options, &exit_code] { exit_code = run(*options); });
}

}  // namespace alplan::cli
