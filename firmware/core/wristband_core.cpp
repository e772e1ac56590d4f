#include "wristband_core.h"

namespace alplan::firmware {

namespace {

BandPassConfig band_of(const CoreConfig& config) {
  return {config.sample_rate_hz, config.low_cut_hz, config.high_cut_hz};
}

}  // namespace

CoreConfig WristbandCore::with_shared_rate(const CoreConfig& config) {
  CoreConfig shared = config;
  shared.peak_detector.sample_rate_hz = config.sample_rate_hz;
  shared.signal_quality.sample_rate_hz = config.sample_rate_hz;
  return shared;
}

ConfigError check_config(const CoreConfig& config) {
  if (!(config.sample_rate_hz >= WristbandCore::kMinSampleRateHz &&
        config.sample_rate_hz <= WristbandCore::kMaxSampleRateHz)) {
    return ConfigError::SampleRate;
  }
  if (!band_is_valid(band_of(config))) return ConfigError::Band;
  PeakDetectorConfig peaks = config.peak_detector;
  peaks.sample_rate_hz = config.sample_rate_hz;
  if (!peak_detector_config_is_valid(peaks)) return ConfigError::PeakDetector;
  SignalQualityConfig quality = config.signal_quality;
  quality.sample_rate_hz = config.sample_rate_hz;
  if (!signal_quality_config_is_valid(quality)) return ConfigError::SignalQuality;
  if (!beat_tracker_config_is_valid(config.beat_tracker)) return ConfigError::BeatTracker;
  if (config.window_ms < WristbandCore::kMinWindowMs || config.window_ms > WristbandCore::kMaxWindowMs) {
    return ConfigError::Window;
  }
  if (config.hop_ms < 1000 || config.hop_ms > config.window_ms) return ConfigError::Hop;
  return ConfigError::None;
}

const char* config_error_name(ConfigError error) {
  switch (error) {
    case ConfigError::None: return "none";
    case ConfigError::SampleRate: return "sample rate outside 25-500 Hz";
    case ConfigError::Band: return "pass band not within 0 < low < high < 0.45 * sample rate";
    case ConfigError::PeakDetector: return "peak detector windows do not fit the sample rate";
    case ConfigError::SignalQuality: return "signal quality settings out of range";
    case ConfigError::BeatTracker: return "beat tracker settings out of range";
    case ConfigError::Window: return "window outside 5-60 s";
    case ConfigError::Hop: return "hop outside 1 s to the window";
  }
  return "unknown";
}

WristbandCore::WristbandCore(const CoreConfig& config)
    : config_(with_shared_rate(config)),
      error_(check_config(config)),
      filter_(band_of(config_)),
      detector_(config_.peak_detector),
      tracker_(config_.beat_tracker),
      quality_(config_.signal_quality) {
  if (error_ != ConfigError::None) return;
  latency_ms_ = static_cast<double>(detector_.latency_samples() + 1) * 1000.0 / sample_rate();
  settle_samples_ = static_cast<uint64_t>(kSettleMs * sample_rate() / 1000.0);
  schedule_reading(0);
}

void WristbandCore::schedule_reading(uint32_t index) {
  const double due_ms =
      static_cast<double>(config_.window_ms) + latency_ms_ + static_cast<double>(index) * config_.hop_ms;
  const double due_sample = due_ms * sample_rate() / 1000.0;
  uint64_t sample = static_cast<uint64_t>(due_sample);
  if (static_cast<double>(sample) < due_sample) ++sample;
  next_reading_sample_ = sample;
}

CoreStep WristbandCore::push_sample(float raw) {
  CoreStep step;
  if (error_ != ConfigError::None) return step;
  const uint64_t index = samples_++;
  const float filtered = filter_.process(raw);
  quality_.process(raw, filtered);
  const PeakDetection detection = detector_.process(filtered);
  if (detection.detected && detection.peak.sample_index >= settle_samples_) {
    step.peak_detected = true;
    step.beat = tracker_.on_peak(peak_time_ms(detection.peak, config_.sample_rate_hz), detection.peak.amplitude);
    beats_.add(step.beat);
  }
  if (index >= next_reading_sample_) {
    step.reading_ready = true;
    step.reading = make_reading(static_cast<double>(index) * 1000.0 / sample_rate());
    schedule_reading(readings_made_);
  }
  return step;
}

Reading WristbandCore::make_reading(double now_ms) {
  const double end_ms = now_ms - latency_ms_;
  const double start_ms = end_ms - config_.window_ms;
  Reading reading;
  reading.sequence = readings_made_++;
  reading.timestamp_ms = config_.start_time_ms + static_cast<uint64_t>(end_ms + 0.5);
  reading.window_ms = config_.window_ms;
  reading.features =
      window_features(beats_.statistics(start_ms, end_ms), quality_.statistics(start_ms, end_ms), config_.window_ms,
                      config_.thresholds);
  return reading;
}

}  // namespace alplan::firmware
