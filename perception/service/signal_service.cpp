#include "perception/service/signal_service.h"

namespace alplan::perception::service {

SignalService::SignalService(DeviceRegistry registry, std::optional<StressClassifier> classifier,
                             const SignalServiceOptions& options)
    : options_(options),
      registry_(std::move(registry)),
      store_(options.database, options.durability),
      events_(options.event_queue_capacity) {
  if (classifier) detector_ = std::make_unique<ClassifierStressDetector>(std::move(*classifier), options.smoothing,
                                                                      options.calibration);
  if (options.commit_veto) store_.set_commit_veto(options.commit_veto);
  IngestOptions ingest;
  ingest.priming_readings = options.priming_readings;
  ingest.max_clock_skew_ms = options.limits.max_clock_skew_ms;
  ingest_ = std::make_unique<ReadingIngest>(store_, detector_.get(), events_, registry_, std::move(ingest));
  handler_ = std::make_unique<RequestHandler>(registry_, *ingest_, metrics_, events_, options.limits, options.error_log);
  ServerOptions server = options.server;
  server.parse_limits.max_body_bytes = options.limits.max_body_bytes;
  server.endpoints = is_loopback_address(server.bind_address) ? Endpoints::All : Endpoints::Readings;
  server_ = std::make_unique<HttpServer>(*handler_, metrics_, server);
  if (options.retention.days > 0.0) {
    retention_ = std::make_unique<RetentionSweeper>(options.database, options.retention, options.error_log);
  }
  if (options.admin_listener) {
    ServerOptions admin = options.admin;
    admin.endpoints = Endpoints::Admin;
    // Off loopback the admin endpoints need TLS as much as the readings do.
    if (!is_loopback_address(admin.bind_address)) {
      admin.tls_certificate_file = server.tls_certificate_file;
      admin.tls_key_file = server.tls_key_file;
    }
    admin_server_ = std::make_unique<HttpServer>(*handler_, metrics_, admin);
  }
}

SignalService::~SignalService() { stop(); }

void SignalService::start() {
  if (admin_server_) admin_server_->start();
  try {
    server_->start();
  } catch (...) {
    if (admin_server_) admin_server_->stop();
    throw;
  }
  if (retention_) retention_->start();
}

void SignalService::stop() {
  if (retention_) retention_->stop();
  server_->stop();
  if (admin_server_) admin_server_->stop();
  events_.close();
}

namespace {

std::string url_of(const ServerOptions& server, std::uint16_t port) {
  // A wildcard address is not one to connect to; loopback reaches it.
  const std::string& host = server.bind_address;
  const bool wildcard = host == "0.0.0.0" || host == "::";
  const char* scheme = server.tls_certificate_file.empty() ? "http://" : "https://";
  return scheme + (wildcard ? std::string("127.0.0.1") : host) + ":" + std::to_string(port);
}

}  // namespace

std::string SignalService::url() const { return url_of(options_.server, server_->port()); }

std::string SignalService::admin_url() const {
  if (!admin_server_) return {};
  ServerOptions admin = options_.admin;
  if (!is_loopback_address(admin.bind_address)) admin.tls_certificate_file = options_.server.tls_certificate_file;
  return url_of(admin, admin_server_->port());
}

}  // namespace alplan::perception::service
