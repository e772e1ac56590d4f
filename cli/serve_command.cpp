// alplan serve --port P --db FILE --tokens FILE [--bind ADDR] [--model FILE]
//              [--max-body BYTES] [--max-batch N] [--threads N] [--io-threads N]
//              [--max-connections N] [--request-timeout MS] [--sync full|normal]
//              [--no-stress] [--duration S] [--max-clock-skew MS] [--events-out -|FILE]
//              [--tls-cert PEM --tls-key PEM | --insecure-http] [--max-connections-per-client N]
//              [--admin-bind ADDR] [--admin-port P] [--detailed-metrics] [--retention-days D]
//              [--deliberate --emotion E|--face IMAGE [--problem P] [--camera DIR] ...]
// The signal service (perception/service/signal_service.h): wristbands POST
// readings, the service stores them, detects stress per senior and, with
// --events-out, writes each stress event as a JSON line to stdout ("-") or a
// file made mode 0600 (the in-process queue's consumer here; the
// deliberation loop consumes the same queue). Seniors' names and states are
// health data: without --events-out they are in the database only. Runs until
// SIGINT or SIGTERM (or --duration seconds), then stops cleanly: exit 0.
// With --deliberate the consumer is the deliberation loop too: each
// "stressed" event runs layers 2-4 (deliberation_run.h) for that senior, one
// event at a time, while the service keeps taking readings.
// Bad options, tokens file (also one that others may read), model or
// database, or an address that cannot be bound: exit 2.
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <memory>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/deliberation_run.h"
#include "cli/perceive_common.h"
#include "cli/service_flags.h"
#include "perception/service/private_file.h"
#include "perception/service/signal_service.h"

namespace alplan::cli {
namespace {

namespace service = perception::service;

struct ServeOptions {
  ServiceFlags service;
  bool no_stress = false;
  std::size_t max_body = 64 * 1024;
  std::size_t max_batch = 12;
  std::size_t threads = 4;
  std::size_t io_threads = 1;
  std::size_t max_connections = 1024;
  long request_timeout_ms = 10000;
  double duration_s = 0.0;
  std::int64_t max_clock_skew_ms = service::kDefaultMaxClockSkewMs;
  std::string events_out;
  std::size_t max_connections_per_client = 256;
  double retention_days = 0.0;
  bool detailed_metrics = false;
  bool deliberate = false;
  DeliberationSettings deliberation;
};

// The deliberation loop, when --deliberate: made before the service starts,
// so that bad settings stop `serve` at once.
std::unique_ptr<Deliberator> make_deliberator(const ServeOptions& o) {
  if (!o.deliberate) return nullptr;
  if (o.no_stress) throw CommandInputError("--deliberate needs stress detection; drop --no-stress");
  try {
    return std::make_unique<Deliberator>(o.deliberation);
  } catch (const std::exception& e) {
    throw CommandInputError(std::string("--deliberate: ") + e.what());
  }
}

// Runs the deliberation for one stress event; a failure is reported and the
// service goes on (one senior's bad run must not stop the others' readings).
void deliberate_on_event(Deliberator& deliberator, const service::StressEvent& e) {
  std::cout << "[service] " << e.senior << " is stressed (" << e.device << "): deliberating" << std::endl;
  try {
    perception::StressState state;
    state.stressed = true;
    state.stressed_fraction = e.stressed_fraction;
    state.votes = e.votes;
    const int code = deliberator.on_stress(e.senior, state);
    std::cout << "[service] deliberation for " << e.senior << " ended with exit " << code << std::endl;
  } catch (const std::exception& error) {
    std::cerr << "serve: deliberation for " << e.senior << " failed: " << error.what() << "\n";
  }
}

std::optional<perception::StressClassifier> classifier_of(const ServeOptions& o) {
  if (o.no_stress) return std::nullopt;
  return load_classifier(o.service.model, "serve");
}

void print_event(std::ostream& out, const service::StressEvent& e) {
  const nlohmann::json line = {{"event", e.stressed ? "stressed" : "calm"}, {"senior", e.senior},
                               {"device", e.device}, {"t_ms", e.t_ms},
                               {"stressed_fraction", e.stressed_fraction}, {"votes", e.votes}};
  out << line.dump() << std::endl;
}

// Where --events-out sends the events: stdout, a private file (appended), or
// nowhere (null).
std::unique_ptr<std::ostream> open_events_out(const std::string& destination) {
  if (destination.empty()) return nullptr;
  if (destination == "-") return std::make_unique<std::ostream>(std::cout.rdbuf());
  service::make_private_file(destination);
  auto file = std::make_unique<std::ofstream>(destination, std::ios::app);
  if (!*file) throw CommandInputError(destination + ": error: cannot open the events file");
  return file;
}

service::SignalServiceOptions serve_options(const ServeOptions& o) {
  service::SignalServiceOptions options = service_options(o.service);
  options.server.handler_threads = o.threads;
  options.server.io_threads = o.io_threads;
  options.server.max_connections = o.max_connections;
  options.server.request_timeout = std::chrono::milliseconds(o.request_timeout_ms);
  options.limits.max_body_bytes = o.max_body;
  options.limits.max_batch = o.max_batch;
  options.limits.max_clock_skew_ms = o.max_clock_skew_ms;
  options.limits.detailed_metrics = o.detailed_metrics;
  options.server.max_connections_per_client = o.max_connections_per_client;
  options.retention.days = o.retention_days;
  return options;
}

int run_serve(const ServeOptions& o) {
  const sigset_t signals = block_stop_signals();
  std::unique_ptr<service::SignalService> signal_service;
  std::unique_ptr<Deliberator> deliberator;
  std::unique_ptr<std::ostream> events_out;
  try {
    check_transport(o.service);
    deliberator = make_deliberator(o);
    service::DeviceRegistry registry = read_private_registry(o.service.tokens);
    events_out = open_events_out(o.events_out);
    signal_service =
        std::make_unique<service::SignalService>(std::move(registry), classifier_of(o), serve_options(o));
    signal_service->start();
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return kExitInputError;
  }
  std::cout << "serving on " << signal_service->url() << " (database " << o.service.db << ", "
            << signal_service->registry().size() << " devices)" << std::endl;
  // On stderr: stdout's first line stays the one scripts read the URL from.
  std::cerr << "serve: admin on " << signal_service->admin_url() << " (GET /healthz, /metrics)" << std::endl;
  std::thread consumer([&deliberator, &events_out, &events = signal_service->events()] {
    while (true) {
      const std::optional<service::StressEvent> e = events.pop_wait(std::chrono::milliseconds(500));
      if (e) {
        if (events_out) print_event(*events_out, *e);
        if (deliberator && e->stressed) deliberate_on_event(*deliberator, *e);
        if (deliberator && !e->stressed) deliberator->on_calm(e->senior);
      } else if (events.closed()) {
        return;  // closed and drained
      }
    }
  });
  wait_for_stop(signals, o.duration_s);
  signal_service->stop();
  consumer.join();
  const service::IngestCounters c = signal_service->counters();
  std::cerr << "serve: stopped; stored " << c.stored << " readings, " << c.duplicates << " duplicates, "
            << c.became_stressed + c.became_calm << " stress events\n";
  return kExitOk;
}

}  // namespace

void add_serve_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<ServeOptions>();
  CLI::App* s = app.add_subcommand("serve", "The signal service: wristband readings over HTTP, stress events out");
  add_service_flags(*s, o->service);
  s->get_option("--db")->required();
  s->get_option("--tokens")->required();
  s->add_flag("--no-stress", o->no_stress, "Store readings only; no stress detection");
  s->add_option("--max-body", o->max_body, "Largest request body in bytes (413 above)")->check(CLI::PositiveNumber);
  s->add_option("--max-batch", o->max_batch, "Most readings in one POST")->check(CLI::PositiveNumber);
  s->add_option("--threads", o->threads, "Request-handler threads")->check(CLI::PositiveNumber);
  s->add_option("--io-threads", o->io_threads, "Network I/O threads")->check(CLI::PositiveNumber);
  s->add_option("--max-connections", o->max_connections, "Open connections before new ones get 503")
      ->check(CLI::PositiveNumber);
  s->add_option("--request-timeout", o->request_timeout_ms, "Milliseconds for a whole request to arrive (408)")
      ->check(CLI::PositiveNumber);
  s->add_option("--duration", o->duration_s, "Stop after this many seconds (0: until SIGINT/SIGTERM)")
      ->check(CLI::NonNegativeNumber);
  s->add_option("--max-clock-skew", o->max_clock_skew_ms,
                "Milliseconds a reading may be stamped ahead of this machine's clock (422 beyond)")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{86400000}));
  s->add_option("--max-connections-per-client", o->max_connections_per_client,
                "Open connections one client address may hold before its new ones get 503")
      ->check(CLI::PositiveNumber);
  s->add_option("--retention-days", o->retention_days,
                "Delete readings and stress events older than this many days, in the background (0: keep all)")
      ->check(CLI::Range(0.0, 36500.0));
  s->add_flag("--detailed-metrics", o->detailed_metrics,
              "Per-device missing readings and stress transitions in /metrics and /healthz");
  s->add_option("--events-out", o->events_out,
                "Write each stress event as a JSON line to '-' (stdout) or FILE (mode 0600); default: nowhere");
  s->add_flag("--deliberate", o->deliberate,
              "Run the deliberation (emotion, goal, plan, act, repair) for each senior who becomes stressed");
  add_deliberation_options(*s, o->deliberation);
  s->callback([o, &exit_code] { exit_code = run_serve(*o); });
}

}  // namespace alplan::cli
