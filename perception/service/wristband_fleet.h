// N simulated wristbands played against the service in real time (or
// faster): `alplan wristband simulate`, the service tests and the load
// benchmark. Wristband i is device i of the tokens registry; the seniors of
// the first `stressed` devices are under stress for the whole run, the
// others calm. Each wristband makes a reading every 1/rate_hz seconds of
// signal (the core's hop) and uploads as the board does (simulated_wristband.h).
//
// Time: the signal advances `speed` seconds per wall-clock second; back-off
// and HTTP timeouts are in wall-clock time, as the service lives in it. The
// wristbands are shared among `connections` threads, each with one
// keep-alive connection, taking turns like the board's loop (one batch per
// wristband per turn). After the signal ends the fleet keeps uploading until
// every queue is empty or `drain_timeout_s` passes.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "perception/service/device_registry.h"
#include "perception/service/simulated_wristband.h"

namespace alplan::perception::service {

struct FleetOptions {
  std::string url;  // http[s]://host:port; the path /v1/readings is added when the URL has none
  std::string ca_file;  // for https: the CA to check the service's certificate with (empty: the system's)
  std::size_t devices = 4;
  double rate_hz = 0.2;  // readings per wristband per second of signal: 1/hop, 1/window .. 1 Hz
  double duration_s = 120.0;
  double speed = 1.0;
  std::size_t stressed = 0;
  bool typical_subjects = false;  // every senior the typical subject (simulated_wristband.h)
  std::uint64_t seed = 1;
  double sample_rate_hz = 50.0;
  std::uint32_t window_ms = 30000;
  std::uint32_t boot = 0;
  std::size_t batch = 12;
  std::size_t connections = 0;  // 0: min(devices, 8)
  std::chrono::milliseconds http_timeout{8000};
  std::uint32_t retry_initial_ms = 250;
  std::uint32_t retry_max_ms = 5000;
  double drain_timeout_s = 30.0;
  std::uint64_t start_time_ms = 0;  // Unix ms of the first sample; 0: now, or as far back as needed to end now
};

struct DeviceOutcome {
  std::string device;
  std::string senior;
  bool stressed = false;
  WristbandCounters counters;  // latencies_s moved to the summary
  std::uint32_t boot = 0;
  std::vector<std::uint32_t> acknowledged;  // sequence numbers
};

struct FleetSummary {
  std::vector<DeviceOutcome> devices;
  WristbandCounters total;  // summed; latencies_s empty
  std::uint64_t pending = 0;  // still queued at the end
  double latency_p50_s = 0.0, latency_p99_s = 0.0, latency_max_s = 0.0;
  double wall_s = 0.0;
  double signal_s = 0.0;
  // Wall seconds from the start to the first reading made and to the last
  // acknowledgement, and between a wristband's readings.
  double first_reading_wall_s = 0.0;
  double last_acknowledged_wall_s = 0.0;
  double hop_wall_s = 0.0;
  // The rate held: acknowledged / (last - first + one hop), the hop because
  // n readings a hop apart span n - 1 hops. Equals the offered rate when the
  // service keeps up; a backlog stretches the span.
  double acknowledged_per_s() const;
  // Every reading made was acknowledged: none dropped, discarded or left over.
  bool complete() const;
};

class WristbandFleet {
 public:
  // Simulates every wristband's signal. Throws std::invalid_argument for bad
  // options (naming the option) or a registry with fewer devices than asked.
  WristbandFleet(const DeviceRegistry& registry, const FleetOptions& options);
  ~WristbandFleet();

  // Plays the fleet to the end; blocks. Call once.
  FleetSummary run();

  // Readings acknowledged so far, while run() is running (thread-safe).
  std::uint64_t acknowledged_so_far() const { return acknowledged_.load(); }
  std::uint64_t posts_so_far() const { return posts_.load(); }

 private:
  struct WorkerSpan {
    double first_reading_s = -1.0;  // none yet
    double last_acknowledged_s = 0.0;
  };
  WorkerSpan play(std::size_t worker, std::size_t workers, std::chrono::steady_clock::time_point start);

  FleetOptions options_;
  std::string path_;
  HttpEndpoint endpoint_;
  std::vector<std::string> seniors_;
  std::vector<std::unique_ptr<SimulatedWristband>> wristbands_;
  std::atomic<std::uint64_t> acknowledged_{0};
  std::atomic<std::uint64_t> posts_{0};
};

void print_fleet_summary(std::ostream& out, const FleetSummary& summary);

}  // namespace alplan::perception::service
