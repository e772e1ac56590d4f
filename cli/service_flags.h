// What `alplan serve` and `alplan home --live` share to run the signal
// service: its flags, reading the tokens file, the stress classifier, the
// transport check, and stopping on SIGINT/SIGTERM without a handler's
// global state.
#pragma once

#include <csignal>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "perception/service/device_registry.h"
#include "perception/service/signal_service.h"
#include "perception/stress/stress_classifier.h"

namespace CLI {
class App;
}

namespace alplan::cli {

struct ServiceFlags {
  std::uint16_t port = 8080;
  std::string bind = "127.0.0.1";
  std::string db;
  std::string tokens;
  std::string model;
  std::string sync = "full";
  std::string tls_cert;
  std::string tls_key;
  bool insecure_http = false;
  std::string admin_bind = "127.0.0.1";
  std::uint16_t admin_port = 0;
};

// --port, --bind, --db, --tokens, --model, --sync, --tls-cert, --tls-key,
// --insecure-http, --admin-bind, --admin-port (none required here: serve
// requires --db and --tokens, home only with --live).
void add_service_flags(CLI::App& command, ServiceFlags& flags);

// The service's options from the flags; a command sets its own limits on top.
perception::service::SignalServiceOptions service_options(const ServiceFlags& flags);

// Plain HTTP would carry the tokens and the seniors' readings in clear: off
// loopback it takes TLS or an explicit --insecure-http. Throws
// CommandInputError.
void check_transport(const ServiceFlags& flags);

// The tokens file holds every wristband's secret: one others can read is
// refused (CommandInputError naming the fix).
perception::service::DeviceRegistry read_private_registry(const std::string& tokens);

// The classifier from --model, or trained on simulated recordings (0.1 s),
// saying so on stderr as `command` ("serve: ...").
perception::StressClassifier load_classifier(const std::string& model, const std::string& command);

// Blocks SIGINT and SIGTERM in this thread and the ones it starts, so that
// one thread takes them with sigtimedwait() instead of a handler with
// global state.
sigset_t block_stop_signals();

// Returns on SIGINT or SIGTERM, after `duration_s` (0: no limit), or once
// `finished` says so (polled five times a second).
void wait_for_stop(const sigset_t& signals, double duration_s, const std::function<bool()>& finished = {});

}  // namespace alplan::cli
