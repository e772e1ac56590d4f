// What the HTTP side of the service counts: responses by status, rejected
// requests by reason, connections, and the latency of accepted POST
// /v1/readings (from the complete request to the response, the commit
// included; refusals are quick and would flatter it).
// Thread-safe. Rendered with the ingest's counters by render_prometheus() in
// the Prometheus text exposition format (version 0.0.4), which GET /metrics
// serves.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>

#include "perception/service/latency_histogram.h"
#include "perception/service/reading_ingest.h"

namespace alplan::perception::service {

class ServiceMetrics {
 public:
  ServiceMetrics();

  void count_response(unsigned status);
  // `reason` is a short stable label: "malformed_json", "unauthorized", ...
  void count_rejection(const std::string& reason);
  void record_readings_latency(double seconds) { readings_latency_.record(seconds); }

  void connection_opened() { open_connections_.fetch_add(1); }
  void connection_closed() { open_connections_.fetch_sub(1); }
  void connection_refused() { refused_connections_.fetch_add(1); }
  std::int64_t open_connections() const { return open_connections_.load(); }

  const LatencyHistogram& readings_latency() const { return readings_latency_; }
  std::map<std::string, std::uint64_t> rejections() const;
  double uptime_seconds() const;

  // The whole exposition; `missing` is the ingest's missing_by_device().
  // Without `detailed`, nothing per device or senior: missing readings are
  // one total, and stress transitions (with one senior, that senior's state)
  // are left out.
  std::string render_prometheus(const IngestCounters& ingest, const std::map<std::string, std::uint64_t>& missing,
                                std::uint64_t events_dropped, bool detailed = false) const;

 private:
  std::chrono::steady_clock::time_point started_;
  mutable std::mutex mutex_;
  std::map<unsigned, std::uint64_t> responses_;
  std::map<std::string, std::uint64_t> rejections_;
  LatencyHistogram readings_latency_;
  std::atomic<std::int64_t> open_connections_{0};
  std::atomic<std::uint64_t> refused_connections_{0};
};

}  // namespace alplan::perception::service
