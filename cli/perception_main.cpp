// The perception module's entry point (perception_module.h): the same
// command line `alplan` received, parsed here with the perception commands.
#include <CLI/CLI.hpp>

#include <opencv2/core/utils/logger.hpp>

#include "cli/commands.h"
#include "cli/parse_command_line.h"

extern "C" __attribute__((visibility("default"))) int alplan_perception_main(int argc, char** argv) {
  // OpenCV's own warnings ("can't open/read file") would repeat the
  // commands' errors in another voice.
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_ERROR);
  CLI::App app{"alplan: PDDL 2.2 temporal planning toolkit for assisted-living deliberation"};
  app.require_subcommand(1);
  int exit_code = alplan::cli::kExitOk;
  alplan::cli::add_perceive_command(app, exit_code);
  alplan::cli::add_deliberate_command(app, exit_code);
  alplan::cli::add_serve_command(app, exit_code);
  alplan::cli::add_wristband_command(app, exit_code);
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks");
  bench->require_subcommand(1);
  alplan::cli::add_bench_service_command(bench, exit_code);
  alplan::cli::add_bench_soak_command(bench, exit_code);
  return alplan::cli::parse_command_line(app, argc, argv, exit_code);
}
