// alplan: a thin shell over the libraries; the only place CLI11 is used.
#include <CLI/CLI.hpp>

#include <iostream>
#include <string>

#include "benchmarks/harness/build_info.h"
#include "cli/commands.h"
#include "cli/parse_command_line.h"
#ifndef ALPLAN_PLANNER_ONLY
#include "cli/perception_module.h"
#endif

int main(int argc, char** argv) {
#ifndef ALPLAN_PLANNER_ONLY
  if (alplan::cli::runs_in_perception_module(argc, argv)) return alplan::cli::run_perception_command(argc, argv);
#endif
  CLI::App app{"alplan: PDDL 2.2 temporal planning toolkit for assisted-living deliberation"};
  app.require_subcommand(1);
  // Every option's help shows its default (subcommands inherit this).
  app.option_defaults()->always_capture_default();
  app.set_help_all_flag("--help-all", "Print help for every subcommand");
  // Papers cite versions: the project's and the commit the binary was built from.
  const alplan::bench::BuildInfo build = alplan::bench::build_info();
  app.set_version_flag("--version", std::string("alplan ") + ALPLAN_VERSION + " (commit " + build.commit +
                                        (build.dirty ? ", with uncommitted changes" : "") + ")",
                       "Print the version and the commit this binary was built from");
  int exit_code = alplan::cli::kExitOk;
  alplan::cli::add_parse_command(app, exit_code);
  alplan::cli::add_ground_command(app, exit_code);
  alplan::cli::add_validate_command(app, exit_code);
  alplan::cli::add_plan_command(app, exit_code);
  alplan::cli::add_bench_command(app, exit_code);
  alplan::cli::add_fuzz_command(app, exit_code);
#ifndef ALPLAN_PLANNER_ONLY
  alplan::cli::add_scenario_command(app, exit_code);
  alplan::cli::add_gen_command(app, exit_code);
  alplan::cli::add_report_command(app, exit_code);
  // Listed for --help; they run in the perception module (perception_module.h).
  for (const alplan::cli::ModuleCommand& c : alplan::cli::kPerceptionCommands) {
    app.add_subcommand(c.name, c.help)->allow_extras();
  }
  app.get_subcommand("bench")->add_subcommand("service", alplan::cli::kBenchServiceHelp)->allow_extras();
  app.get_subcommand("bench")->add_subcommand("soak", alplan::cli::kBenchSoakHelp)->allow_extras();
  app.get_subcommand("bench")->add_subcommand("home", alplan::cli::kBenchHomeHelp)->allow_extras();
#endif
  return alplan::cli::parse_command_line(app, argc, argv, exit_code);
}
