// alplan bench service [--devices N[,N...]] [--rate HZ] [--duration S] [--speed X]
//                      [--threads N] [--sync full|normal] [--work-dir DIR]
//                      [--tls-cert PEM --tls-key PEM]
// The signal service's load benchmark: for each fleet size, starts a service
// in this process on a free loopback port with a fresh database, plays that
// many simulated wristbands against it (perception/service/wristband_fleet.h),
// stops it, and checks the database: every reading made is stored exactly
// once (zero loss). Prints a Markdown table: readings/s offered and held,
// client-side and server-side latency percentiles. Exit 0 when every run
// lost nothing, 1 otherwise, 2 on bad input.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>

#include "cli/commands.h"
#include "perception/service/signal_service.h"
#include "perception/service/wristband_fleet.h"
#include "perception/stress/simulated_stress_model.h"

namespace alplan::cli {
namespace {

namespace service = perception::service;

struct BenchServiceOptions {
  std::string devices = "100,400,1000";
  double rate_hz = 1.0;
  double duration_s = 60.0;
  double speed = 1.0;
  std::size_t threads = 4;
  std::size_t connections = 8;
  std::string sync = "full";
  std::string work_dir = "build/bench-service";
  // HTTPS with this certificate, which the wristbands then trust (a
  // self-signed one, or give its CA's by making the chain file start with it).
  std::string tls_cert;
  std::string tls_key;
};

struct BenchRow {
  std::size_t devices = 0;
  service::FleetSummary fleet;
  std::uint64_t rows_in_db = 0;
  std::uint64_t missing_acknowledged = 0;  // acknowledged but not in the database
  double server_p50_s = 0.0, server_p99_s = 0.0;
  bool lossless() const {
    return fleet.complete() && rows_in_db == fleet.total.made && missing_acknowledged == 0;
  }
};

service::DeviceRegistry bench_registry(std::size_t devices) {
  std::vector<service::Device> list;
  for (std::size_t i = 0; i < devices; ++i) {
    char id[32], token[64];
    std::snprintf(id, sizeof id, "bench-%05zu", i);
    // Benchmark devices on loopback: tokens need to be distinct, not secret.
    std::snprintf(token, sizeof token, "bench-token-%05zu-%08zx", i, (i * 2654435761U) & 0xffffffffU);
    list.push_back({id, token, std::string("senior-") + std::to_string(i)});
  }
  return service::DeviceRegistry(std::move(list));
}

// How many of the acknowledged readings the database lacks.
std::uint64_t lost_acknowledged(service::ReadingStore& store, const service::FleetSummary& fleet) {
  std::uint64_t lost = 0;
  for (const service::DeviceOutcome& d : fleet.devices) {
    std::set<std::uint32_t> stored;
    for (const service::ReceivedReading& r : store.readings_of(d.device)) {
      if (r.boot == d.boot) stored.insert(r.seq);
    }
    for (const std::uint32_t seq : d.acknowledged) lost += stored.count(seq) == 0 ? 1 : 0;
  }
  return lost;
}

BenchRow run_one(const BenchServiceOptions& o, std::size_t devices, const perception::StressClassifier& model) {
  const std::filesystem::path db = std::filesystem::path(o.work_dir) / ("service-" + std::to_string(devices) + ".db");
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(db.string() + suffix);
  service::DeviceRegistry registry = bench_registry(devices);
  service::SignalServiceOptions options;
  options.database = db;
  options.durability = o.sync == "normal" ? service::Durability::Normal : service::Durability::Full;
  options.server.handler_threads = o.threads;
  options.server.max_connections = 4096;
  options.server.tls_certificate_file = o.tls_cert;
  options.server.tls_key_file = o.tls_key;
  service::FleetOptions fleet_options;
  fleet_options.devices = devices;
  fleet_options.rate_hz = o.rate_hz;
  fleet_options.duration_s = o.duration_s;
  fleet_options.speed = o.speed;
  fleet_options.stressed = devices / 4;
  fleet_options.sample_rate_hz = 25.0;  // the cheapest rate the core takes: the simulator shares the CPU
  fleet_options.connections = o.connections;
  fleet_options.ca_file = o.tls_cert;
  BenchRow row;
  row.devices = devices;
  {
    service::SignalService signal_service(registry, model, options);
    signal_service.start();
    fleet_options.url = signal_service.url();
    service::WristbandFleet fleet(registry, fleet_options);
    row.fleet = fleet.run();
    row.server_p50_s = signal_service.metrics().readings_latency().quantile(0.5);
    row.server_p99_s = signal_service.metrics().readings_latency().quantile(0.99);
    signal_service.stop();
  }
  service::ReadingStore store(db, service::Durability::Normal, service::StoreAccess::ReadOnly);
  row.rows_in_db = store.count_readings();
  row.missing_acknowledged = lost_acknowledged(store, row.fleet);
  return row;
}

void print_row(std::ostream& out, const BenchServiceOptions& o, const BenchRow& r) {
  const double offered = static_cast<double>(r.devices) * o.rate_hz * o.speed;
  // From the first reading made to the last acknowledged: a service that
  // falls behind stretches the span and the rate drops below the offered one.
  const double held = r.fleet.acknowledged_per_s();
  char line[512];
  std::snprintf(line, sizeof line, "| %zu | %.0f | %.0f | %llu | %llu | %llu | %.2f | %.2f | %.2f | %.2f | %llu | %s |\n",
                r.devices, offered, held, static_cast<unsigned long long>(r.fleet.total.made),
                static_cast<unsigned long long>(r.rows_in_db),
                static_cast<unsigned long long>(r.fleet.total.made - std::min(r.fleet.total.made, r.rows_in_db) +
                                                r.missing_acknowledged),
                r.fleet.latency_p50_s * 1e3, r.fleet.latency_p99_s * 1e3, r.server_p50_s * 1e3,
                r.server_p99_s * 1e3, static_cast<unsigned long long>(r.fleet.total.retries),
                r.lossless() ? "yes" : "NO");
  out << line << std::flush;
}

int run_bench_service(const BenchServiceOptions& o) {
  std::vector<std::size_t> sizes;
  std::istringstream list(o.devices);
  for (std::string item; std::getline(list, item, ',');) {
    try {
      sizes.push_back(static_cast<std::size_t>(std::stoul(item)));
    } catch (const std::exception&) {
      std::cerr << "error: --devices: '" << item << "' is not a number\n";
      return kExitInputError;
    }
  }
  try {
    std::filesystem::create_directories(o.work_dir);
    const perception::StressClassifier model = perception::train_simulated_stress_classifier({});
    std::cout << "| wristbands | offered readings/s | held readings/s | made | stored | lost | client p50 ms | "
                 "client p99 ms | server p50 ms | server p99 ms | retries | zero loss |\n"
              << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    bool all_lossless = true;
    for (const std::size_t n : sizes) {
      const BenchRow row = run_one(o, n, model);
      print_row(std::cout, o, row);
      all_lossless = all_lossless && row.lossless();
    }
    return all_lossless ? kExitOk : kExitInvalid;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
}

}  // namespace

void add_bench_service_command(CLI::App* bench, int& exit_code) {
  auto o = std::make_shared<BenchServiceOptions>();
  CLI::App* s = bench->add_subcommand("service", "Load the signal service with simulated wristbands; check zero loss");
  s->add_option("--devices", o->devices, "Fleet sizes, comma-separated");
  s->add_option("--rate", o->rate_hz, "Readings per wristband per second of signal (1/30 to 1)");
  s->add_option("--duration", o->duration_s, "Seconds of signal (the first 30 s fill the first window)")
      ->check(CLI::Range(31.0, 86400.0));
  s->add_option("--speed", o->speed, "Seconds of signal per wall-clock second")->check(CLI::PositiveNumber);
  s->add_option("--threads", o->threads, "The service's request-handler threads")->check(CLI::PositiveNumber);
  s->add_option("--connections", o->connections, "Client threads (keep-alive connections)")->check(CLI::PositiveNumber);
  s->add_option("--sync", o->sync, "full or normal (see alplan serve)")->check(CLI::IsMember({"full", "normal"}));
  s->add_option("--work-dir", o->work_dir, "Where the databases go");
  s->add_option("--tls-cert", o->tls_cert, "Serve HTTPS with this PEM certificate (the wristbands trust it)");
  s->add_option("--tls-key", o->tls_key, "The PEM key of --tls-cert");
  s->callback([o, &exit_code] { exit_code = run_bench_service(*o); });
}

}  // namespace alplan::cli
