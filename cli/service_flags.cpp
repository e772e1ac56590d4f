#include "cli/service_flags.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <ctime>
#include <iostream>
#include <utility>

#include "cli/perceive_common.h"
#include "perception/service/private_file.h"
#include "perception/stress/simulated_stress_model.h"

namespace alplan::cli {

namespace service = perception::service;

void add_service_flags(CLI::App& s, ServiceFlags& o) {
  s.add_option("--port", o.port, "TCP port (0: any free one, printed at start)");
  s.add_option("--db", o.db, "SQLite database file (created when missing)");
  s.add_option("--tokens", o.tokens, "Tokens file: device token senior, one device a line");
  s.add_option("--bind", o.bind, "Address to listen on");
  s.add_option("--model", o.model, "Stress classifier file (StressClassifier::save); default: train on simulation");
  s.add_option("--sync", o.sync, "full: fsync every commit; normal: survive a crash, not a power cut")
      ->check(CLI::IsMember({"full", "normal"}));
  s.add_option("--tls-cert", o.tls_cert, "PEM certificate (chain) to serve HTTPS with; with --tls-key");
  s.add_option("--tls-key", o.tls_key, "PEM private key of --tls-cert (must be mode 0600 or stricter)");
  s.add_flag("--insecure-http", o.insecure_http,
             "Allow plain HTTP on a non-loopback address (tokens and readings in clear)");
  s.add_option("--admin-bind", o.admin_bind, "Address of the /healthz and /metrics listener (keep it loopback)");
  s.add_option("--admin-port", o.admin_port, "Port of the /healthz and /metrics listener (0: any free one, printed)");
}

service::SignalServiceOptions service_options(const ServiceFlags& o) {
  service::SignalServiceOptions options;
  options.database = o.db;
  options.durability = o.sync == "normal" ? service::Durability::Normal : service::Durability::Full;
  options.server.bind_address = o.bind;
  options.server.port = o.port;
  options.server.tls_certificate_file = o.tls_cert;
  options.server.tls_key_file = o.tls_key;
  options.admin.bind_address = o.admin_bind;
  options.admin.port = o.admin_port;
  return options;
}

// The message starts as a failed bind's does, since it is the same refusal
// to listen there.
void check_transport(const ServiceFlags& o) {
  const bool tls = !o.tls_cert.empty() || !o.tls_key.empty();
  if (tls && (o.tls_cert.empty() || o.tls_key.empty())) {
    throw CommandInputError("--tls-cert and --tls-key go together");
  }
  if (tls) {
    if (const std::string problem = service::private_file_problem(o.tls_key, "TLS key"); !problem.empty()) {
      throw CommandInputError(problem);
    }
    return;
  }
  if (o.insecure_http) return;
  for (const auto& [address, port] : {std::pair{o.bind, o.port}, std::pair{o.admin_bind, o.admin_port}}) {
    if (service::is_loopback_address(address)) continue;
    throw CommandInputError("cannot listen on " + address + ":" + std::to_string(port) +
                            ": plain HTTP off loopback would carry tokens and readings in clear; give --tls-cert "
                            "and --tls-key, or --insecure-http");
  }
}

service::DeviceRegistry read_private_registry(const std::string& tokens) {
  if (const std::string problem = service::private_file_problem(tokens, "tokens file"); !problem.empty()) {
    throw CommandInputError(problem);
  }
  return service::read_device_registry_file(tokens);
}

perception::StressClassifier load_classifier(const std::string& model, const std::string& command) {
  if (!model.empty()) return perception::StressClassifier::load(model);
  std::cerr << command << ": no --model given; training the stress classifier on simulated recordings\n";
  return perception::train_simulated_stress_classifier({});
}

sigset_t block_stop_signals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  return signals;
}

void wait_for_stop(const sigset_t& signals, double duration_s, const std::function<bool()>& finished) {
  const auto start = std::chrono::steady_clock::now();
  while (true) {
    const timespec poll{0, 200 * 1000 * 1000};
    if (sigtimedwait(&signals, nullptr, &poll) > 0) return;
    if (finished && finished()) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (duration_s > 0.0 && elapsed >= duration_s) return;
  }
}

}  // namespace alplan::cli
