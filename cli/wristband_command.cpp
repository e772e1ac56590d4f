// alplan wristband simulate --devices N --rate HZ --url URL --tokens FILE
//                           [--duration S] [--stressed K] [--typical-subjects]
//                           [--seed S] [--speed X]
//                           [--sample-rate HZ] [--connections N] [--boot B]
//                           [--batch N] [--drain-timeout S] [--json] [--cacert PEM]
//   Plays N simulated wristbands against the service (perception/service/
//   wristband_fleet.h) and prints a summary. Exit 0 when every reading was
//   acknowledged, 1 when some were not (service down past the drain timeout,
//   refused, or dropped from a full queue), 2 on bad input.
// alplan wristband tokens --devices N [--prefix wb-] [--out FILE [--force]]
//   Writes a tokens file for N devices with fresh random tokens (device wb-01
//   is worn by senior senior-01, ...), for `serve --tokens` and `simulate
//   --tokens`. The file is created mode 0600 (the tokens are secrets); an
//   existing one is refused unless --force.
#include <CLI/CLI.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "perception/service/device_registry.h"
#include "perception/service/private_file.h"
#include "perception/service/random_token.h"
#include "perception/service/wristband_fleet.h"

namespace alplan::cli {
namespace {

namespace service = perception::service;

struct SimulateOptions {
  service::FleetOptions fleet;
  std::string tokens;
  double http_timeout_s = 8.0;
  bool json = false;
};

struct TokensOptions {
  std::size_t devices = 4;
  std::string prefix = "wb-";
  std::string out;
  bool force = false;
};

nlohmann::json summary_json(const service::FleetSummary& s) {
  const service::WristbandCounters& t = s.total;
  return {{"wristbands", s.devices.size()}, {"made", t.made},          {"sent", t.sent},
          {"posts", t.posts},               {"acknowledged", t.acknowledged}, {"stored", t.stored},
          {"duplicates", t.duplicates},     {"retries", t.retries},   {"discarded", t.discarded},
          {"dropped", t.dropped},           {"pending", s.pending},   {"latency_p50_ms", s.latency_p50_s * 1000.0},
          {"latency_p99_ms", s.latency_p99_s * 1000.0}, {"wall_s", s.wall_s}, {"complete", s.complete()}};
}

int run_simulate(const SimulateOptions& o) {
  try {
    const service::DeviceRegistry registry = service::read_device_registry_file(o.tokens);
    service::FleetOptions fleet_options = o.fleet;
    fleet_options.http_timeout = std::chrono::milliseconds(static_cast<long>(o.http_timeout_s * 1000.0));
    service::WristbandFleet fleet(registry, fleet_options);
    const service::FleetSummary summary = fleet.run();
    if (o.json) {
      std::cout << summary_json(summary).dump(2) << "\n";
    } else {
      service::print_fleet_summary(std::cout, summary);
    }
    return summary.complete() ? kExitOk : kExitInvalid;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

int run_tokens(const TokensOptions& o) {
  try {
    std::vector<service::Device> devices;
    const int width = o.devices < 100 ? 2 : static_cast<int>(std::to_string(o.devices).size());
    for (std::size_t i = 1; i <= o.devices; ++i) {
      std::ostringstream number;
      number << std::setw(width) << std::setfill('0') << i;
      devices.push_back({o.prefix + number.str(), service::random_token(), "senior-" + number.str()});
    }
    const service::DeviceRegistry registry(std::move(devices));
    if (o.out.empty()) {
      service::write_device_registry(std::cout, registry);
      return kExitOk;
    }
    std::ostringstream text;
    service::write_device_registry(text, registry);
    // Created 0600 before a byte of a token is in it.
    const int fd = service::create_private_file(o.out, o.force);
    service::write_and_close(fd, text.str(), o.out);
    return kExitOk;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

}  // namespace

void add_wristband_command(CLI::App& app, int& exit_code) {
  CLI::App* w = app.add_subcommand("wristband", "Simulated wristbands for the signal service");
  w->require_subcommand(1);

  auto o = std::make_shared<SimulateOptions>();
  service::FleetOptions& f = o->fleet;
  CLI::App* s = w->add_subcommand("simulate", "Play N simulated wristbands against the service");
  s->add_option("--devices", f.devices, "Wristbands (the first N of the tokens file)")->required()
      ->check(CLI::PositiveNumber);
  s->add_option("--rate", f.rate_hz, "Readings per wristband per second of signal (1/30 to 1; the board: 0.2)")
      ->required();
  s->add_option("--url", f.url, "The service, http://host:port or https://host[:port]")->required();
  s->add_option("--cacert", f.ca_file, "For https: the CA certificate(s) to check the service's with (default: the system's)");
  s->add_option("--tokens", o->tokens, "Tokens file (device token senior), as given to serve")->required();
  s->add_option("--duration", f.duration_s, "Seconds of signal per wristband");
  s->add_option("--stressed", f.stressed, "The first K wristbands' seniors are stressed");
  s->add_flag("--typical-subjects", f.typical_subjects,
              "Every senior the simulator's typical subject (70 bpm; +15 bpm under stress), not a random one");
  s->add_option("--seed", f.seed, "Seed of the subjects and signals");
  s->add_option("--speed", f.speed, "Seconds of signal per wall-clock second")->check(CLI::PositiveNumber);
  s->add_option("--sample-rate", f.sample_rate_hz, "PPG samples per second (25-500)");
  s->add_option("--connections", f.connections, "Client threads, one keep-alive connection each (0: min(N, 8))");
  s->add_option("--boot", f.boot, "The wristbands' boot counter");
  s->add_option("--batch", f.batch, "Most readings per POST (the board: 12)")->check(CLI::PositiveNumber);
  s->add_option("--drain-timeout", f.drain_timeout_s, "Seconds to keep delivering after the signal ends");
  s->add_option("--http-timeout", o->http_timeout_s, "Seconds before a POST counts as failed")
      ->check(CLI::PositiveNumber);
  s->add_flag("--json", o->json, "Print the summary as JSON");
  s->callback([o, &exit_code] { exit_code = run_simulate(*o); });

  auto t = std::make_shared<TokensOptions>();
  CLI::App* k = w->add_subcommand("tokens", "Write a tokens file with random tokens for N devices");
  k->add_option("--devices", t->devices, "Devices")->required()->check(CLI::Range(1, 100000));
  k->add_option("--prefix", t->prefix, "Device id prefix");
  k->add_option("--out", t->out, "File to write, mode 0600 (default: stdout)");
  k->add_flag("--force", t->force, "Overwrite an existing --out file");
  k->callback([t, &exit_code] { exit_code = run_tokens(*t); });
}

}  // namespace alplan::cli
