// alplan bench soak [--devices N] [--duration S] [--speed X] [--rate HZ]
//                   [--commit-failures P] [--restart-every S] [--stalled-clients N]
//                   [--connections N] [--threads N] [--seed S] [--work-dir DIR]
// The signal service's soak benchmark (perception/service/service_soak.h):
// N simulated wristbands for S seconds of signal against one service while
// commits fail at random, the service restarts and clients stall; then
// every reading and stress event is accounted for. Prints a Markdown table.
// Exit 0 when nothing was lost, no event was raised twice or missed; 1
// otherwise; 2 on bad input. The README's figures are a 10-minute run; CI
// runs none of it.
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/perception_module.h"
#include "perception/service/service_soak.h"

namespace alplan::cli {
namespace {

namespace service = perception::service;

int run_bench_soak(const service::SoakOptions& o) {
  try {
    const service::SoakReport report = service::run_soak(o);
    service::print_soak_report(std::cout, o, report);
    return report.passed() ? kExitOk : kExitInvalid;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

}  // namespace

void add_bench_soak_command(CLI::App* bench, int& exit_code) {
  auto o = std::make_shared<service::SoakOptions>();
  CLI::App* s = bench->add_subcommand("soak", kBenchSoakHelp);
  s->add_option("--devices", o->devices, "Simulated wristbands")->check(CLI::PositiveNumber);
  s->add_option("--duration", o->duration_s, "Seconds of signal (the first 30 s fill the first window)")
      ->check(CLI::Range(31.0, 86400.0));
  s->add_option("--speed", o->speed, "Seconds of signal per wall-clock second")->check(CLI::Range(1.0, 100.0));
  s->add_option("--rate", o->rate_hz, "Readings per wristband per second of signal (the board: 0.2)");
  s->add_option("--commit-failures", o->commit_failure_rate, "Fraction of commits made to fail, at random");
  s->add_option("--restart-every", o->restart_every_s, "Stop and restart the service every S wall seconds (0: never)");
  s->add_option("--stalled-clients", o->stalled_clients, "Connections that stall mid-request, over and over");
  s->add_option("--connections", o->connections, "The fleet's client threads")->check(CLI::PositiveNumber);
  s->add_option("--threads", o->handler_threads, "The service's request-handler threads")->check(CLI::PositiveNumber);
  s->add_option("--seed", o->seed, "Seed of the faults and the signals");
  s->add_option("--work-dir", o->work_dir, "Where the database goes");
  s->callback([o, &exit_code] { exit_code = run_bench_soak(*o); });
}

}  // namespace alplan::cli
