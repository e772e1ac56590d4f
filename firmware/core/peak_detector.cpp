#include "peak_detector.h"

#include <float.h>

namespace alplan::firmware {

namespace {

uint32_t half_width(float window_ms, float sample_rate_hz) {
  const float samples = window_ms * sample_rate_hz / 1000.0f;
  const float half = (samples - 1.0f) / 2.0f;
  return half <= 0.0f ? 0u : static_cast<uint32_t>(half + 0.5f);
}


struct WindowSamples {
  uint32_t half_peak;
  uint32_t half_beat;
  uint32_t max_block;
};

WindowSamples window_samples(const PeakDetectorConfig& config) {
  const float fs = config.sample_rate_hz;
  return {half_width(config.peak_window_ms, fs), half_width(config.beat_window_ms, fs),
          static_cast<uint32_t>(config.max_block_ms * fs / 1000.0f + 0.5f)};
}

}  // namespace

bool peak_detector_config_is_valid(const PeakDetectorConfig& config) {
  if (!(config.sample_rate_hz > 0.0f) || !(config.max_block_ms > 0.0f) || !(config.mean_time_constant_s > 0.0f) ||
      !(config.offset_fraction >= 0.0f) || !(config.beat_window_ms < 1.0e6f)) {
    return false;
  }
  const WindowSamples w = window_samples(config);
  return w.half_peak >= 1 && w.half_beat > w.half_peak && 2 * w.half_beat + 2 < PeakDetector::kHistoryCapacity &&
         w.max_block >= 2 * w.half_peak + 1;
}

PeakDetector::PeakDetector(const PeakDetectorConfig& config) {
  valid_ = peak_detector_config_is_valid(config);
  if (!valid_) return;
  const WindowSamples w = window_samples(config);
  half_peak_ = w.half_peak;
  half_beat_ = w.half_beat;
  max_block_ = w.max_block;
  offset_fraction_ = config.offset_fraction;
  mean_floor_rate_ = 1.0f / (config.mean_time_constant_s * config.sample_rate_hz);
}

float PeakDetector::value_at(int64_t index) const {
  if (index < 0) return 0.0f;
  return history_[static_cast<uint64_t>(index) & (kHistoryCapacity - 1)];
}

float PeakDetector::squared_at(int64_t index) const {
  const float value = value_at(index);
  return value > 0.0f ? value * value : 0.0f;
}

void PeakDetector::recompute_sums() {
  const int64_t long_width = 2 * static_cast<int64_t>(half_beat_) + 1;
  const int64_t centre = newest_ - half_beat_;
  float long_sum = 0.0f;
  for (int64_t i = newest_ - long_width + 1; i <= newest_; ++i) long_sum += squared_at(i);
  float short_sum = 0.0f;
  for (int64_t i = centre - half_peak_; i <= centre + static_cast<int64_t>(half_peak_); ++i) short_sum += squared_at(i);
  long_sum_ = long_sum;
  short_sum_ = short_sum;
  since_recompute_ = 0;
}

// The vertex of the least-squares parabola y = a + b x + c x^2 through the
// samples at index + x, |x| <= half_peak_, relative to index; 0 when the fit
// is not a maximum, and at most one sample either way (the maximum sample is
// within half a sample of a true vertex, so a larger shift means a lopsided
// top, not a better estimate).
float PeakDetector::vertex_offset(int64_t index) const {
  const int64_t k = half_peak_;
  float sum_y = 0.0f, sum_xy = 0.0f, sum_xxy = 0.0f, sum_xx = 0.0f, sum_xxxx = 0.0f;
  for (int64_t x = -k; x <= k; ++x) {
    const float fx = static_cast<float>(x);
    const float y = value_at(index + x);
    sum_y += y;
    sum_xy += fx * y;
    sum_xxy += fx * fx * y;
    sum_xx += fx * fx;
    sum_xxxx += fx * fx * fx * fx;
  }
  const float count = static_cast<float>(2 * k + 1);
  const float mean_xx = sum_xx / count;
  const float slope = sum_xy / sum_xx;
  const float curvature = (sum_xxy - mean_xx * sum_y) / (sum_xxxx - count * mean_xx * mean_xx);
  if (!(curvature < 0.0f)) return 0.0f;
  const float offset = -slope / (2.0f * curvature);
  if (offset > 1.0f) return 1.0f;
  if (offset < -1.0f) return -1.0f;
  return offset;
}

PeakDetection PeakDetector::process(float filtered_sample) {
  if (!valid_) return {};
  ++newest_;
  history_[static_cast<uint64_t>(newest_) & (kHistoryCapacity - 1)] = filtered_sample;

  const int64_t n = newest_;
  const int64_t h1 = half_peak_;
  const int64_t h2 = half_beat_;
  long_sum_ += squared_at(n) - squared_at(n - (2 * h2 + 1));
  short_sum_ += squared_at(n - h2 + h1) - squared_at(n - h2 - h1 - 1);
  if (++since_recompute_ >= 2 * half_beat_ + 1) recompute_sums();
  if (long_sum_ < 0.0f) long_sum_ = 0.0f;
  if (short_sum_ < 0.0f) short_sum_ = 0.0f;

  const int64_t centre = n - h2;
  if (centre < h2) return {};  // the long average is not yet full
  if (mean_count_ < UINT32_MAX) ++mean_count_;
  const float cumulative_rate = 1.0f / static_cast<float>(mean_count_);
  const float rate = cumulative_rate > mean_floor_rate_ ? cumulative_rate : mean_floor_rate_;
  mean_squared_ += (squared_at(centre) - mean_squared_) * rate;
  return evaluate_centre(centre);
}

PeakDetection PeakDetector::evaluate_centre(int64_t centre) {
  const float value = value_at(centre);
  // Refine the maximum as soon as the samples after it are in: the buffer
  // may not hold its left side any longer by the time a long block ends.
  if (in_block_ && !refined_ && centre == block_max_index_ + static_cast<int64_t>(half_peak_)) {
    block_fraction_ = vertex_offset(block_max_index_);
    refined_ = true;
  }
  const float ma_peak = short_sum_ / static_cast<float>(peak_window_samples());
  const float ma_beat = long_sum_ / static_cast<float>(beat_window_samples());
  if (ma_peak > ma_beat + offset_fraction_ * mean_squared_) {
    if (!in_block_) {
      in_block_ = true;
      block_start_ = centre;
      block_max_ = -FLT_MAX;
    }
    if (value > block_max_) {
      block_max_ = value;
      block_max_index_ = centre;
      refined_ = false;
    }
    return {};
  }
  if (!in_block_) return {};
  in_block_ = false;
  const int64_t width = centre - block_start_;
  if (width < static_cast<int64_t>(peak_window_samples()) || width > static_cast<int64_t>(max_block_)) return {};
  if (!refined_) block_fraction_ = vertex_offset(block_max_index_);  // the newest sample is at most h2 ahead
  PeakDetection detection;
  detection.detected = true;
  detection.peak.sample_index = static_cast<uint64_t>(block_max_index_);
  detection.peak.fraction = block_fraction_;
  detection.peak.amplitude = block_max_;
  return detection;
}

double peak_time_ms(const Peak& peak, float sample_rate_hz) {
  return (static_cast<double>(peak.sample_index) + static_cast<double>(peak.fraction)) * 1000.0 /
         static_cast<double>(sample_rate_hz);
}

}  // namespace alplan::firmware
