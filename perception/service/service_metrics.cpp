#include "perception/service/service_metrics.h"

#include <sstream>

namespace alplan::perception::service {
namespace {

void family(std::ostringstream& out, const char* name, const char* type, const char* help) {
  out << "# HELP " << name << ' ' << help << "\n# TYPE " << name << ' ' << type << '\n';
}

}  // namespace

ServiceMetrics::ServiceMetrics() : started_(std::chrono::steady_clock::now()) {}

void ServiceMetrics::count_response(unsigned status) {
  const std::lock_guard lock(mutex_);
  responses_[status] += 1;
}

void ServiceMetrics::count_rejection(const std::string& reason) {
  const std::lock_guard lock(mutex_);
  rejections_[reason] += 1;
}

std::map<std::string, std::uint64_t> ServiceMetrics::rejections() const {
  const std::lock_guard lock(mutex_);
  return rejections_;
}

double ServiceMetrics::uptime_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
}

std::string ServiceMetrics::render_prometheus(const IngestCounters& ingest,
                                              const std::map<std::string, std::uint64_t>& missing,
                                              std::uint64_t events_dropped, bool detailed) const {
  std::ostringstream out;
  out.precision(9);
  family(out, "alplan_readings_stored_total", "counter", "Readings stored on first arrival.");
  out << "alplan_readings_stored_total " << ingest.stored << '\n';
  family(out, "alplan_readings_duplicate_total", "counter", "Readings already stored (re-sent), acknowledged again.");
  out << "alplan_readings_duplicate_total " << ingest.duplicates << '\n';
  family(out, "alplan_readings_late_total", "counter", "Readings stored but older than the senior's newest voted one.");
  out << "alplan_readings_late_total " << ingest.late << '\n';
  family(out, "alplan_readings_missing", "gauge", "Sequence numbers below a device's highest that are not stored.");
  if (detailed) {
    for (const auto& [device, count] : missing) {
      out << "alplan_readings_missing{device=\"" << device << "\"} " << count << '\n';
    }
    family(out, "alplan_stress_events_total", "counter", "Stress decisions that flipped, by the new state.");
    out << "alplan_stress_events_total{state=\"stressed\"} " << ingest.became_stressed << '\n';
    out << "alplan_stress_events_total{state=\"calm\"} " << ingest.became_calm << '\n';
  } else {
    std::uint64_t total = 0;
    for (const auto& entry : missing) total += entry.second;
    out << "alplan_readings_missing " << total << '\n';
  }
  family(out, "alplan_stress_events_dropped_total", "counter", "Events dropped from the full in-process queue.");
  out << "alplan_stress_events_dropped_total " << events_dropped << '\n';
  family(out, "alplan_commits_total", "counter", "SQLite transactions committed (one per group of batches).");
  out << "alplan_commits_total " << ingest.commits << '\n';
  family(out, "alplan_batches_committed_total", "counter", "POSTed batches committed.");
  out << "alplan_batches_committed_total " << ingest.batches << '\n';
  family(out, "alplan_commit_failures_total", "counter", "Transactions that failed (answered 503).");
  out << "alplan_commit_failures_total " << ingest.failed_commits << '\n';
  {
    const std::lock_guard lock(mutex_);
    family(out, "alplan_requests_rejected_total", "counter", "Requests refused, by reason.");
    for (const auto& [reason, count] : rejections_) {
      out << "alplan_requests_rejected_total{reason=\"" << reason << "\"} " << count << '\n';
    }
    family(out, "alplan_http_responses_total", "counter", "Responses sent, by status code.");
    for (const auto& [status, count] : responses_) {
      out << "alplan_http_responses_total{code=\"" << status << "\"} " << count << '\n';
    }
  }
  family(out, "alplan_readings_request_seconds", "summary",
         "Latency of accepted POST /v1/readings, from the complete request to the response (commit included).");
  for (const double q : {0.5, 0.9, 0.99, 0.999}) {
    out << "alplan_readings_request_seconds{quantile=\"" << q << "\"} " << readings_latency_.quantile(q) << '\n';
  }
  out << "alplan_readings_request_seconds_sum " << readings_latency_.sum_seconds() << '\n';
  out << "alplan_readings_request_seconds_count " << readings_latency_.count() << '\n';
  family(out, "alplan_connections_open", "gauge", "Client connections open now.");
  out << "alplan_connections_open " << open_connections_.load() << '\n';
  family(out, "alplan_connections_refused_total", "counter", "Connections refused over the connection limit.");
  out << "alplan_connections_refused_total " << refused_connections_.load() << '\n';
  family(out, "alplan_uptime_seconds", "gauge", "Seconds since the service started.");
  out << "alplan_uptime_seconds " << uptime_seconds() << '\n';
  return out.str();
}

}  // namespace alplan::perception::service
