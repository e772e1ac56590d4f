// The signal service in one object (the paper's Flask service, rebuilt):
// wristbands POST readings over HTTP; they are stored in SQLite, run through
// the stress detector per senior, and stress events come out of events()
// for the deliberation loop in the same process.
//
//   SignalService service(registry, classifier, options);
//   service.start();                        // listening on service.port()
//   while (auto e = service.events().pop_wait(1s)) deliberate(*e);
//   service.stop();
//
// No global state: two services run side by side in one process on
// different ports and databases. Stopping and making a new service on the
// same database (and port) continues where the old one stopped.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "perception/service/device_registry.h"
#include "perception/service/http_server.h"
#include "perception/service/reading_ingest.h"
#include "perception/service/reading_store.h"
#include "perception/service/request_handler.h"
#include "perception/service/retention_sweeper.h"
#include "perception/service/service_metrics.h"
#include "perception/service/stress_event_queue.h"
#include "perception/stress/stress_classifier.h"
#include "perception/stress/stress_detector.h"

namespace alplan::perception::service {

struct SignalServiceOptions {
  std::filesystem::path database;
  Durability durability = Durability::Full;
  // The wristbands' listener. On a loopback address it serves the admin
  // endpoints too (nobody off the machine reaches either); otherwise only
  // POST /v1/readings.
  ServerOptions server{};
  // The operator's listener for GET /healthz and /metrics, loopback by
  // default, on its own port (0: any free one, see admin_port()).
  ServerOptions admin{};
  bool admin_listener = true;
  HandlerLimits limits{};
  StressSmoothing smoothing{};
  // No per-senior baseline here yet: the baseline lives in the detector's
  // memory only, and priming after a restart replays the latest readings,
  // which would make a stressed senior's latest readings their baseline. It
  // needs storing with the readings first.
  StressCalibration calibration{0};
  std::size_t event_queue_capacity = 1024;
  // Per device, the latest stored readings replayed into the detector at
  // start-up: four smoothing windows, so the hysteresis settles where it was.
  std::size_t priming_readings = 24;
  // Fault injection (tests, the soak benchmark): asked at every COMMIT of
  // readings, true fails it (SqliteDatabase::set_commit_veto). Called on the
  // committing thread only. Empty in production.
  std::function<bool()> commit_veto;
  ErrorLog error_log = log_to_stderr;
  // Readings older than this are deleted in the background (days 0: never).
  RetentionOptions retention{};
};

class SignalService {
 public:
  // Opens (or creates) the database. Without a classifier readings are
  // stored but no stress is detected. Throws SqliteError or
  // std::invalid_argument (bad smoothing) before anything listens.
  SignalService(DeviceRegistry registry, std::optional<StressClassifier> classifier,
                const SignalServiceOptions& options);
  ~SignalService();
  SignalService(const SignalService&) = delete;
  SignalService& operator=(const SignalService&) = delete;

  // Throws std::runtime_error when the address cannot be bound.
  void start();
  // Finishes the requests being handled (their commits complete), closes
  // every connection, and closes the event queue. Idempotent.
  void stop();

  std::uint16_t port() const { return server_->port(); }
  std::string url() const;  // http[s]://<bind address>:<port>
  // The admin listener's port and URL (0 and empty without one).
  std::uint16_t admin_port() const { return admin_server_ ? admin_server_->port() : 0; }
  std::string admin_url() const;

  StressEventQueue& events() { return events_; }
  IngestCounters counters() const { return ingest_->counters(); }
  const ServiceMetrics& metrics() const { return metrics_; }
  RequestHandler& handler() { return *handler_; }
  const DeviceRegistry& registry() const { return registry_; }

 private:
  SignalServiceOptions options_;
  DeviceRegistry registry_;
  ReadingStore store_;
  std::unique_ptr<StressDetector> detector_;
  StressEventQueue events_;
  std::unique_ptr<ReadingIngest> ingest_;
  ServiceMetrics metrics_;
  std::unique_ptr<RequestHandler> handler_;
  std::unique_ptr<RetentionSweeper> retention_;
  std::unique_ptr<HttpServer> admin_server_;
  std::unique_ptr<HttpServer> server_;  // last: stopped and destroyed first
};

}  // namespace alplan::perception::service
