// The wristband's signal chain in one object: feed raw PPG samples one by
// one at a fixed rate; every `hop_ms` a reading comes out with the features
// of the last `window_ms` (defaults: a 30 s window every 5 s).
//
//   raw -> BandPassFilter -> PeakDetector (Elgendi 2013) -> BeatTracker -> BeatWindow
//   raw and filtered -> SignalQuality (motion evidence)
//   BeatWindow + SignalQuality -> window_features -> Reading
//
// Timing. Peaks are confirmed up to PeakDetector::latency_samples() after
// they happen, so a reading made at sample time `now` describes the window
// ending at now - report_latency_ms(), whose beats are then all known. The
// first reading comes when the first full window is complete. Peaks in the
// first kSettleMs are ignored: the filter starts settled on a constant, and
// the pulse is not one, so its first two seconds (about 1 / low cut) ring.
// A beat's time is that of its band-passed peak, which trails the true
// systolic peak by the filter's group delay (0-70 ms, more at higher rates).
//
// No heap, no exceptions: everything is sized at compile time (about 8 KB),
// and a bad configuration is reported by config_error() rather than thrown;
// a core with a bad configuration ignores its samples.
#pragma once

#include <float.h>
#include <stdint.h>

#include "band_pass_filter.h"
#include "beat_tracker.h"
#include "beat_window.h"
#include "peak_detector.h"
#include "reading.h"
#include "signal_quality.h"
#include "window_features.h"

namespace alplan::firmware {

struct CoreConfig {
  float sample_rate_hz = 100.0f;  // 25-500 Hz
  uint32_t window_ms = 30000;     // 5-60 s
  uint32_t hop_ms = 5000;         // 1 s to the window
  uint64_t start_time_ms = 0;     // the clock's value at sample 0 (e.g. Unix ms)
  float low_cut_hz = 0.5f;
  float high_cut_hz = 5.0f;
  // The sample_rate_hz fields of these two are ignored: the core's is used.
  PeakDetectorConfig peak_detector{};
  SignalQualityConfig signal_quality{};
  BeatTrackerConfig beat_tracker{};
  FeatureThresholds thresholds{};
};

enum class ConfigError { None, SampleRate, Band, PeakDetector, SignalQuality, BeatTracker, Window, Hop };

ConfigError check_config(const CoreConfig& config);
const char* config_error_name(ConfigError error);

// What one sample produced.
struct CoreStep {
  bool peak_detected = false;  // a peak was confirmed; `beat` says what it made
  BeatEvent beat{};
  bool reading_ready = false;  // a window closed; `reading` holds it
  Reading reading{};
};

class WristbandCore {
 public:
  static constexpr float kMinSampleRateHz = 25.0f;
  static constexpr float kMaxSampleRateHz = 500.0f;
  static constexpr uint32_t kMinWindowMs = 5000;
  static constexpr uint32_t kMaxWindowMs = 60000;
  static constexpr uint32_t kSettleMs = 2000;

  explicit WristbandCore(const CoreConfig& config);

  ConfigError config_error() const { return error_; }

  CoreStep push_sample(float raw);

  // How far behind the newest sample a reading's window ends.
  double report_latency_ms() const { return latency_ms_; }
  uint64_t samples_seen() const { return samples_; }
  const BeatTracker& beat_tracker() const { return tracker_; }

 private:
  static CoreConfig with_shared_rate(const CoreConfig& config);
  double sample_rate() const { return static_cast<double>(config_.sample_rate_hz); }
  void schedule_reading(uint32_t index);
  Reading make_reading(double now_ms);

  CoreConfig config_;
  ConfigError error_;
  BandPassFilter filter_;
  PeakDetector detector_;
  BeatTracker tracker_;
  BeatWindow beats_;
  SignalQuality quality_;
  double latency_ms_ = 0.0;
  uint64_t samples_ = 0;
  uint32_t readings_made_ = 0;
  uint64_t next_reading_sample_ = 0;
  uint64_t settle_samples_ = 0;
};

}  // namespace alplan::firmware
