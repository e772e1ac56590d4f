// One simulated wristband on the host: the PPG simulator's signal for a
// subject (stressed or not) fed sample by sample into the firmware's
// WristbandCore, its readings encoded by the firmware's encoder into the
// board's bounded ReadingQueue, and uploaded in batches with the board's
// decisions (firmware/core/upload_policy.h, retry_backoff.h) — the board's
// reading_uploader.cpp with the ESP32 parts replaced by a host HTTP client.
// Unsent readings stay queued and go out oldest first when the service is
// back. Not thread-safe: one thread drives a wristband.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "firmware/core/reading_encoder.h"
#include "firmware/core/reading_queue.h"
#include "firmware/core/retry_backoff.h"
#include "firmware/core/wristband_core.h"
#include "perception/service/readings_client.h"
#include "perception/stress/ppg_simulator.h"

namespace alplan::perception::service {

// The board's offline store (board_config.h: 240 readings, 20 min at a 5 s hop).
inline constexpr std::size_t kWristbandQueueReadings = 240;
inline constexpr std::size_t kWristbandPostBytes = 4096;

struct WristbandSpec {
  std::string device_id;
  std::string token;
  std::uint32_t boot = 0;
  bool stressed = false;
  // A random subject of the simulator's population (resting HR 72 +- 8 bpm,
  // its own stress response), or the typical one (SubjectProfile{} and
  // StressResponse{}: 70 bpm, +15 bpm under stress, HRV x0.55).
  bool typical_subject = false;
  std::uint64_t seed = 1;  // the subject and the signal
  double sample_rate_hz = 50.0;
  double duration_s = 120.0;  // of signal
  std::uint32_t window_ms = 30000;
  std::uint32_t hop_ms = 5000;
  std::uint64_t start_time_ms = 0;  // Unix ms at the first sample
  std::size_t batch = 12;
  std::uint32_t retry_initial_ms = 250;
  std::uint32_t retry_max_ms = 5000;
};

struct WristbandCounters {
  std::uint64_t made = 0;          // readings out of the core
  std::uint64_t sent = 0;          // readings put in POSTs (re-sends counted again)
  std::uint64_t acknowledged = 0;  // released after a 2xx
  std::uint64_t stored = 0;        // ... that the service stored now
  std::uint64_t duplicates = 0;    // ... that it had already
  std::uint64_t posts = 0;
  std::uint64_t retries = 0;       // POSTs that failed and were kept for later
  std::uint64_t discarded = 0;     // readings refused with a 4xx and dropped
  std::uint64_t dropped = 0;       // readings pushed out of the full queue
  std::vector<double> latencies_s; // of POSTs that got an HTTP answer
};

class SimulatedWristband {
 public:
  // Simulates the whole signal up front. Throws std::invalid_argument for a
  // device id the encoder refuses or a configuration the core refuses.
  explicit SimulatedWristband(const WristbandSpec& spec);

  // Feeds the core the samples up to `signal_s` seconds of signal (capped
  // at the duration) and queues the readings that come out.
  void advance_to(double signal_s);
  bool signal_done() const { return next_sample_ >= recording_.size(); }

  bool has_pending() const { return !queue_->empty(); }
  std::size_t pending() const { return queue_->size(); }
  // Time of the next allowed POST (after a failure, the back-off's).
  std::chrono::steady_clock::time_point next_attempt() const { return next_attempt_; }

  // POSTs the oldest queued readings (up to `batch`) to `path` and acts on
  // the status as the board does. Returns the HTTP status (or negative
  // transport error); 0 when nothing was queued.
  int upload(ReadingsClient& client, const std::string& path);

  const WristbandSpec& spec() const { return spec_; }
  const WristbandCounters& counters() const { return counters_; }
  // The sequence numbers (of spec().boot) of every acknowledged reading, in
  // acknowledgement order.
  const std::vector<std::uint32_t>& acknowledged_sequences() const { return acknowledged_; }

 private:
  void queue_reading(const firmware::Reading& reading);
  void release(const firmware::QueuedBatch& batch, const std::string& response_body);

  WristbandSpec spec_;
  std::vector<float> recording_;
  std::size_t next_sample_ = 0;
  std::unique_ptr<firmware::WristbandCore> core_;  // 12 KB: heap, not stack
  std::unique_ptr<firmware::ReadingQueue<kWristbandQueueReadings>> queue_;
  std::vector<std::uint32_t> queued_sequences_;  // parallel to the queue's entries, oldest first
  firmware::RetryBackoff backoff_;
  std::mt19937 jitter_;
  std::chrono::steady_clock::time_point next_attempt_{};
  WristbandCounters counters_;
  std::vector<std::uint32_t> acknowledged_;
  std::vector<char> body_;
};

}  // namespace alplan::perception::service
