#include "perception/service/wristband_fleet.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <optional>
#include <thread>

#include "stats/quantile.h"

namespace alplan::perception::service {
namespace {

std::uint64_t unix_ms_now() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::milliseconds>(
                                        std::chrono::system_clock::now().time_since_epoch())
                                        .count());
}

// Nearest rank (stats/quantile.h); 0 where no reading was answered.
double percentile(const std::vector<double>& sorted, double q) {
  return sorted.empty() ? 0.0 : stats::nearest_rank_of_sorted(sorted, q);
}

void check_options(const FleetOptions& o, std::size_t registered) {
  if (o.devices == 0) throw std::invalid_argument("--devices must be at least 1");
  if (o.devices > registered) {
    throw std::invalid_argument("--devices " + std::to_string(o.devices) + " but the tokens file lists only " +
                                std::to_string(registered));
  }
  if (o.stressed > o.devices) throw std::invalid_argument("--stressed must be at most --devices");
  const double window_s = o.window_ms / 1000.0;
  if (!(o.rate_hz >= 1.0 / window_s - 1e-9 && o.rate_hz <= 1.0)) {
    throw std::invalid_argument("--rate must be between 1/window (" + std::to_string(1.0 / window_s) +
                                ") and 1 reading per second (the core's hop is 1 s to the window)");
  }
  if (!(o.duration_s > window_s)) throw std::invalid_argument("--duration must be longer than the 30 s window");
  if (!(o.speed > 0.0)) throw std::invalid_argument("--speed must be positive");
  if (!(o.drain_timeout_s >= 0.0)) throw std::invalid_argument("--drain-timeout must not be negative");
}

}  // namespace

double FleetSummary::acknowledged_per_s() const {
  const double span = last_acknowledged_wall_s - first_reading_wall_s + hop_wall_s;
  return span > 0.0 ? static_cast<double>(total.acknowledged) / span : 0.0;
}

bool FleetSummary::complete() const {
  return pending == 0 && total.dropped == 0 && total.discarded == 0 && total.acknowledged == total.made;
}

WristbandFleet::WristbandFleet(const DeviceRegistry& registry, const FleetOptions& options) : options_(options) {
  check_options(options_, registry.size());
  endpoint_ = parse_http_url(options_.url);
  path_ = endpoint_.path.empty() || endpoint_.path == "/" ? "/v1/readings" : endpoint_.path;
  // A CA file that cannot be loaded is found here, not in a worker thread.
  if (endpoint_.tls) ReadingsClient(endpoint_, options_.http_timeout, options_.ca_file);
  if (options_.connections == 0) options_.connections = std::min<std::size_t>(options_.devices, 8);
  options_.connections = std::min(options_.connections, options_.devices);
  // Faster than real time, the signal starts in the past so that it ends
  // now: no reading is ever stamped ahead of the wall clock, which the
  // service refuses beyond its allowed skew.
  const auto ahead_ms = static_cast<std::uint64_t>(options_.duration_s * 1000.0 * (1.0 - 1.0 / std::max(1.0, options_.speed)));
  const std::uint64_t start_ms = options_.start_time_ms != 0 ? options_.start_time_ms : unix_ms_now() - ahead_ms;
  for (std::size_t i = 0; i < options_.devices; ++i) {
    const Device& device = registry.devices()[i];
    WristbandSpec spec;
    spec.device_id = device.id;
    spec.token = device.token;
    spec.boot = options_.boot;
    spec.stressed = i < options_.stressed;
    spec.typical_subject = options_.typical_subjects;
    spec.seed = options_.seed * 1000003ULL + i;
    spec.sample_rate_hz = options_.sample_rate_hz;
    spec.duration_s = options_.duration_s;
    spec.window_ms = options_.window_ms;
    spec.hop_ms = static_cast<std::uint32_t>(std::lround(1000.0 / options_.rate_hz));
    spec.start_time_ms = start_ms;
    spec.batch = options_.batch;
    spec.retry_initial_ms = options_.retry_initial_ms;
    spec.retry_max_ms = options_.retry_max_ms;
    wristbands_.push_back(std::make_unique<SimulatedWristband>(spec));
    seniors_.push_back(device.senior);
  }
}

WristbandFleet::~WristbandFleet() = default;

WristbandFleet::WorkerSpan WristbandFleet::play(std::size_t worker, std::size_t workers,
                                                std::chrono::steady_clock::time_point start) {
  using clock = std::chrono::steady_clock;
  WorkerSpan span;
  const auto since_start = [start] { return std::chrono::duration<double>(clock::now() - start).count(); };
  ReadingsClient client(endpoint_, options_.http_timeout, options_.ca_file);
  std::vector<SimulatedWristband*> mine;
  for (std::size_t i = worker; i < wristbands_.size(); i += workers) mine.push_back(wristbands_[i].get());
  std::optional<clock::time_point> drain_until;
  while (true) {
    const clock::time_point now = clock::now();
    const double signal_s = std::chrono::duration<double>(now - start).count() * options_.speed;
    bool signal_done = true, pending = false, posted = false;
    for (SimulatedWristband* w : mine) {
      w->advance_to(signal_s);
      signal_done = signal_done && w->signal_done();
      if (span.first_reading_s < 0.0 && w->counters().made > 0) span.first_reading_s = since_start();
    }
    for (SimulatedWristband* w : mine) {
      if (w->has_pending() && clock::now() >= w->next_attempt()) {
        const std::uint64_t before = w->counters().acknowledged;
        w->upload(client, path_);
        acknowledged_.fetch_add(w->counters().acknowledged - before);
        if (w->counters().acknowledged > before) span.last_acknowledged_s = since_start();
        posts_.fetch_add(1);
        posted = true;
      }
      pending = pending || w->has_pending();
    }
    if (signal_done && !pending) return span;
    if (signal_done && !drain_until) {
      drain_until = now + std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(options_.drain_timeout_s));
    }
    if (drain_until && now >= *drain_until) return span;
    if (!posted) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

FleetSummary WristbandFleet::run() {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::thread> threads;
  std::vector<WorkerSpan> spans(options_.connections);
  for (std::size_t w = 0; w < options_.connections; ++w) {
    threads.emplace_back([this, w, start, &spans] { spans[w] = play(w, options_.connections, start); });
  }
  for (std::thread& t : threads) t.join();
  FleetSummary summary;
  summary.first_reading_wall_s = std::numeric_limits<double>::max();
  for (const WorkerSpan& s : spans) {
    if (s.first_reading_s >= 0.0) summary.first_reading_wall_s = std::min(summary.first_reading_wall_s, s.first_reading_s);
    summary.last_acknowledged_wall_s = std::max(summary.last_acknowledged_wall_s, s.last_acknowledged_s);
  }
  if (summary.first_reading_wall_s == std::numeric_limits<double>::max()) summary.first_reading_wall_s = 0.0;
  summary.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.signal_s = options_.duration_s;
  summary.hop_wall_s = 1.0 / (options_.rate_hz * options_.speed);
  std::vector<double> latencies;
  for (std::size_t i = 0; i < wristbands_.size(); ++i) {
    const SimulatedWristband& w = *wristbands_[i];
    DeviceOutcome d{w.spec().device_id, seniors_[i], w.spec().stressed, w.counters(), w.spec().boot,
                    w.acknowledged_sequences()};
    latencies.insert(latencies.end(), d.counters.latencies_s.begin(), d.counters.latencies_s.end());
    d.counters.latencies_s.clear();
    WristbandCounters& t = summary.total;
    t.made += d.counters.made;
    t.sent += d.counters.sent;
    t.acknowledged += d.counters.acknowledged;
    t.stored += d.counters.stored;
    t.duplicates += d.counters.duplicates;
    t.posts += d.counters.posts;
    t.retries += d.counters.retries;
    t.discarded += d.counters.discarded;
    t.dropped += d.counters.dropped;
    summary.pending += w.pending();
    summary.devices.push_back(std::move(d));
  }
  std::sort(latencies.begin(), latencies.end());
  summary.latency_p50_s = percentile(latencies, 0.5);
  summary.latency_p99_s = percentile(latencies, 0.99);
  summary.latency_max_s = latencies.empty() ? 0.0 : latencies.back();
  return summary;
}

void print_fleet_summary(std::ostream& out, const FleetSummary& s) {
  const WristbandCounters& t = s.total;
  out << "wristbands: " << s.devices.size() << ", signal " << s.signal_s << " s in " << s.wall_s << " s wall\n"
      << "readings made: " << t.made << "\n"
      << "sent: " << t.sent << " in " << t.posts << " POSTs (re-sends included)\n"
      << "acknowledged: " << t.acknowledged << " (stored " << t.stored << ", duplicates " << t.duplicates << ")\n"
      << "retries: " << t.retries << "\n"
      << "discarded (4xx): " << t.discarded << ", dropped (queue full): " << t.dropped << ", pending: " << s.pending
      << "\n"
      << "latency p50: " << s.latency_p50_s * 1000.0 << " ms, p99: " << s.latency_p99_s * 1000.0
      << " ms, max: " << s.latency_max_s * 1000.0 << " ms\n"
      << "acknowledged/s (first reading to last acknowledgement): " << s.acknowledged_per_s() << "\n"
      << (s.complete() ? "complete: every reading acknowledged\n" : "INCOMPLETE: some readings not acknowledged\n");
}

}  // namespace alplan::perception::service
