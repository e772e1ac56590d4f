// The service's HTTP semantics, without sockets: one parsed request in, one
// response out. The network side (http_server.h) reads requests and writes
// what this returns; tests and the fuzzer call it directly.
//
//   POST /v1/readings  Authorization: Bearer <device token>,
//                      Content-Type: application/json,
//                      body: one reading or an array of 1..max_batch (the
//                      firmware's JSON, reading_message.h)
//     200 {"stored":2,"duplicates":1,"results":[{"boot":3,"seq":41,"status":"duplicate"},
//                                                {"boot":3,"seq":42,"status":"stored"},...]}
//         results in request order; a duplicate was stored before, so the
//         device may release it too. Sent only after the commit.
//     400 malformed JSON, wrong types, missing or unknown keys, values out of
//         range, empty or too long batches (the device drops the batch)
//     401 no or unknown token (WWW-Authenticate: Bearer)
//     403 a reading names another device than the token's
//     413 body over max_body     415 Content-Type is not application/json
//     422 a reading stamped beyond the server's clock plus the allowed skew
//     503 the database failed (Retry-After: 1); the body says no more (the
//         file and SQL go to the error log)
//   GET /healthz       200 {"status":"ok","devices":N,"stored_since_start":N,
//                      "uptime_s":S} (and "stress_events":N when detailed)
//   GET /metrics       200 Prometheus text format (service_metrics.h)
//   A listener serves the readings, the admin endpoints, or both (Endpoints);
//   the others are 404 there.
//   other paths 404, other methods on these paths 405 (with Allow).
//
// Every error body is {"error":"<what, naming the place>","reason":"<label>"}
// where the label is the one counted in alplan_requests_rejected_total. The
// 4xx codes match what the board does with them (firmware/core/
// upload_policy.h): 401/403 keep the readings for a retry (a token can be
// fixed on the server), other 4xx drop a batch that would never be accepted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include <boost/beast/http/message.hpp>
#include <boost/beast/http/string_body.hpp>

#include "perception/service/device_registry.h"
#include "perception/service/reading_ingest.h"
#include "perception/service/service_metrics.h"
#include "perception/service/stress_event_queue.h"

namespace alplan::perception::service {

using HttpRequest = boost::beast::http::request<boost::beast::http::string_body>;
using HttpResponse = boost::beast::http::response<boost::beast::http::string_body>;

struct HandlerLimits {
  std::size_t max_body_bytes = 64 * 1024;  // a full batch of 12 is about 4 KB
  std::size_t max_batch = 12;              // the firmware's batch size
  // A reading stamped later than the server's clock plus this is refused
  // (422): the wristband's clock is wrong, and the reading would blind its
  // senior's detector (reading_ingest.h).
  std::int64_t max_clock_skew_ms = kDefaultMaxClockSkewMs;
  // /metrics and /healthz carry nothing per device or senior (device ids,
  // stress transitions) unless this is set.
  bool detailed_metrics = false;
};

// Which endpoints a listener serves: the wristbands' one POST /v1/readings,
// the operator's /healthz and /metrics, or both (a loopback-only service).
enum class Endpoints { Readings, Admin, All };

// Where the handler reports what it keeps out of its answers (the database's
// file and SQL behind a 503, an exception behind a 500).
using ErrorLog = std::function<void(const std::string&)>;
// Writes each message as a line on standard error.
void log_to_stderr(const std::string& message);

// A JSON error response, counted neither here nor anywhere (callers count).
HttpResponse error_response(unsigned status, const std::string& reason, const std::string& message,
                            unsigned version = 11, bool keep_alive = false);

class RequestHandler {
 public:
  // Everything referenced must outlive the handler.
  RequestHandler(const DeviceRegistry& registry, ReadingIngest& ingest, ServiceMetrics& metrics,
                 const StressEventQueue& events, const HandlerLimits& limits, ErrorLog error_log = log_to_stderr);

  // Never throws: anything unexpected becomes a 500 with a JSON error.
  // Counts the response (and the rejection reason) in the metrics.
  HttpResponse handle(const HttpRequest& request, Endpoints served = Endpoints::All);

  const HandlerLimits& limits() const { return limits_; }

 private:
  HttpResponse route(const HttpRequest& request, Endpoints served);
  HttpResponse post_readings(const HttpRequest& request);
  HttpResponse healthz(const HttpRequest& request) const;
  HttpResponse metrics(const HttpRequest& request) const;

  const DeviceRegistry& registry_;
  ReadingIngest& ingest_;
  ServiceMetrics& metrics_;
  const StressEventQueue& events_;
  HandlerLimits limits_;
  ErrorLog error_log_;
};

}  // namespace alplan::perception::service
