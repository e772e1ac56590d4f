#include "perception/service/request_handler.h"

#include <chrono>
#include <iostream>
#include <string_view>

#include <boost/beast/http/field.hpp>
#include <boost/beast/http/verb.hpp>
#include <nlohmann/json.hpp>

#include "perception/service/reading_message.h"
#include "perception/service/sqlite_database.h"

namespace alplan::perception::service {
namespace {

namespace http = boost::beast::http;
using nlohmann::json;

// A request answered with an error; thrown inside the handler only.
struct Rejection {
  unsigned status;
  std::string reason;
  std::string message;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

std::string_view path_of(std::string_view target) {
  const auto query = target.find('?');
  return query == std::string_view::npos ? target : target.substr(0, query);
}

HttpResponse json_response(unsigned status, const json& body, const HttpRequest& request) {
  HttpResponse response{static_cast<http::status>(status), request.version()};
  response.set(http::field::server, "alplan");
  response.set(http::field::content_type, "application/json");
  response.keep_alive(request.keep_alive());
  response.body() = body.dump();
  response.prepare_payload();
  return response;
}

const Device& authenticate(const DeviceRegistry& registry, const HttpRequest& request) {
  const auto header = request.find(http::field::authorization);
  if (header == request.end()) throw Rejection{401, "unauthorized", "missing Authorization: Bearer <device token>"};
  const std::string_view value = trim({header->value().data(), header->value().size()});
  const auto space = value.find(' ');
  if (space == std::string_view::npos || !iequals(value.substr(0, space), "Bearer")) {
    throw Rejection{401, "unauthorized", "Authorization must be 'Bearer <device token>'"};
  }
  const std::string_view token = trim(value.substr(space + 1));
  // Refused before any comparison, so a huge token costs no more than a valid one.
  if (token.size() > kMaxTokenLength) {
    throw Rejection{401, "unauthorized", "token longer than " + std::to_string(kMaxTokenLength) + " characters"};
  }
  const Device* device = registry.authenticate(token);
  if (device == nullptr) throw Rejection{401, "unauthorized", "unknown device token"};
  return *device;
}

void require_json_content(const HttpRequest& request) {
  const auto header = request.find(http::field::content_type);
  if (header == request.end()) throw Rejection{415, "unsupported_media_type", "missing Content-Type: application/json"};
  std::string_view type{header->value().data(), header->value().size()};
  type = trim(type.substr(0, type.find(';')));
  if (!iequals(type, "application/json")) {
    throw Rejection{415, "unsupported_media_type", "Content-Type must be application/json"};
  }
}

std::int64_t unix_ms_now() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

// The place of reading i in the body, as the parser names it.
std::string place_of(const HttpRequest& request, std::size_t i) {
  const bool single = request.body().find_first_not_of(" \t\r\n") == request.body().find('{');
  return single ? std::string("reading") : "readings[" + std::to_string(i) + "]";
}

void require_clock_plausible(const HttpRequest& request, const std::vector<ReceivedReading>& readings,
                             std::int64_t max_skew_ms) {
  const std::int64_t now = unix_ms_now();
  for (std::size_t i = 0; i < readings.size(); ++i) {
    if (readings[i].t_ms <= static_cast<std::uint64_t>(now + max_skew_ms)) continue;
    throw Rejection{422, "clock_ahead",
                    place_of(request, i) + ".t_ms: " + std::to_string(readings[i].t_ms) +
                        " is ahead of the server's clock (" + std::to_string(now) + ") by more than the allowed " +
                        std::to_string(max_skew_ms) + " ms; the wristband's clock is wrong; nothing was stored"};
  }
}

}  // namespace

void log_to_stderr(const std::string& message) { std::cerr << message << std::endl; }

HttpResponse error_response(unsigned status, const std::string& reason, const std::string& message,
                            unsigned version, bool keep_alive) {
  HttpResponse response{static_cast<http::status>(status), version};
  response.set(http::field::server, "alplan");
  response.set(http::field::content_type, "application/json");
  if (status == 401) response.set(http::field::www_authenticate, "Bearer");
  if (status == 503) response.set(http::field::retry_after, "1");
  response.keep_alive(keep_alive);
  // dump() with replacement: a message may quote bytes that are not UTF-8.
  response.body() = json{{"error", message}, {"reason", reason}}.dump(-1, ' ', false, json::error_handler_t::replace);
  response.prepare_payload();
  return response;
}

RequestHandler::RequestHandler(const DeviceRegistry& registry, ReadingIngest& ingest, ServiceMetrics& metrics,
                               const StressEventQueue& events, const HandlerLimits& limits, ErrorLog error_log)
    : registry_(registry),
      ingest_(ingest),
      metrics_(metrics),
      events_(events),
      limits_(limits),
      error_log_(std::move(error_log)) {}

HttpResponse RequestHandler::handle(const HttpRequest& request, Endpoints served) {
  HttpResponse response;
  try {
    try {
      response = route(request, served);
    } catch (const Rejection& r) {
      metrics_.count_rejection(r.reason);
      response = error_response(r.status, r.reason, r.message, request.version(), request.keep_alive());
      if (r.status == 405) {
        response.set(http::field::allow, path_of({request.target().data(), request.target().size()}) == "/v1/readings" ? "POST" : "GET, HEAD");
      }
    }
  } catch (const std::exception& e) {
    metrics_.count_rejection("internal_error");
    if (error_log_) error_log_(std::string("signal service: internal error: ") + e.what());
    response = error_response(500, "internal_error", "internal error; the service's log says more", request.version());
  }
  metrics_.count_response(response.result_int());
  return response;
}

HttpResponse RequestHandler::route(const HttpRequest& request, Endpoints served) {
  const std::string_view path = path_of({request.target().data(), request.target().size()});
  const http::verb method = request.method();
  if (served == Endpoints::Readings && path != "/v1/readings") {
    throw Rejection{404, "not_found", "no such path; this listener serves POST /v1/readings only"};
  }
  if (served == Endpoints::Admin && path != "/healthz" && path != "/metrics") {
    throw Rejection{404, "not_found", "no such path; this listener serves GET /healthz and GET /metrics only"};
  }
  if (path == "/v1/readings") {
    if (method != http::verb::post) throw Rejection{405, "method_not_allowed", "/v1/readings takes POST"};
    const auto start = std::chrono::steady_clock::now();
    HttpResponse response = post_readings(request);
    metrics_.record_readings_latency(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return response;
  }
  if (path == "/healthz" || path == "/metrics") {
    if (method != http::verb::get && method != http::verb::head) {
      throw Rejection{405, "method_not_allowed", std::string(path) + " takes GET"};
    }
    HttpResponse response = path == "/healthz" ? healthz(request) : metrics(request);
    if (method == http::verb::head) {
      response.body().clear();  // keeps the Content-Length of the GET, as HEAD should
    }
    return response;
  }
  throw Rejection{404, "not_found", "no such path; the service serves POST /v1/readings, GET /healthz, GET /metrics"};
}

HttpResponse RequestHandler::post_readings(const HttpRequest& request) {
  if (request.body().size() > limits_.max_body_bytes) {
    throw Rejection{413, "body_too_large",
                    "body of " + std::to_string(request.body().size()) + " bytes is over the limit of " +
                        std::to_string(limits_.max_body_bytes)};
  }
  const Device& device = authenticate(registry_, request);
  require_json_content(request);
  std::vector<ReceivedReading> readings;
  try {
    readings = parse_readings(request.body(), limits_.max_batch);
  } catch (const ReadingFormatError& e) {
    throw Rejection{400, e.reason(), e.what()};
  }
  for (std::size_t i = 0; i < readings.size(); ++i) {
    if (readings[i].device != device.id) {
      throw Rejection{403, "wrong_device",
                      place_of(request, i) + ".device: '" + readings[i].device +
                          "' is not the device this token belongs to"};
    }
  }
  require_clock_plausible(request, readings, limits_.max_clock_skew_ms);
  std::vector<bool> stored;
  try {
    stored = ingest_.ingest(device.senior, readings);
  } catch (const SqliteError& e) {
    // The file and the SQL are the operator's business, not the network's.
    if (error_log_) error_log_(std::string("signal service: commit failed: ") + e.what());
    throw Rejection{503, "storage_error", "readings not stored (storage error), retry later"};
  }
  json results = json::array();
  std::size_t new_count = 0;
  for (std::size_t i = 0; i < readings.size(); ++i) {
    new_count += stored[i] ? 1 : 0;
    results.push_back({{"boot", readings[i].boot}, {"seq", readings[i].seq}, {"status", stored[i] ? "stored" : "duplicate"}});
  }
  return json_response(200, {{"stored", new_count}, {"duplicates", readings.size() - new_count}, {"results", results}},
                       request);
}

HttpResponse RequestHandler::healthz(const HttpRequest& request) const {
  const IngestCounters counters = ingest_.counters();
  json body = {{"status", "ok"},
               {"devices", registry_.size()},
               {"stored_since_start", counters.stored},
               {"uptime_s", metrics_.uptime_seconds()}};
  // With one senior, a count of stress events is that senior's state.
  if (limits_.detailed_metrics) body["stress_events"] = counters.became_stressed + counters.became_calm;
  return json_response(200, body, request);
}

HttpResponse RequestHandler::metrics(const HttpRequest& request) const {
  HttpResponse response{http::status::ok, request.version()};
  response.set(http::field::server, "alplan");
  response.set(http::field::content_type, "text/plain; version=0.0.4; charset=utf-8");
  response.keep_alive(request.keep_alive());
  response.body() = metrics_.render_prometheus(ingest_.counters(), ingest_.missing_by_device(), events_.dropped(),
                                               limits_.detailed_metrics);
  response.prepare_payload();
  return response;
}

}  // namespace alplan::perception::service
