#include "signal_quality.h"

#include "order_statistics.h"

namespace alplan::firmware {

bool signal_quality_config_is_valid(const SignalQualityConfig& config) {
  return config.sample_rate_hz > 0.0f && config.segment_ms * config.sample_rate_hz >= 1000.0f * 2.0f &&
         config.segment_ms >= 1000.0f && config.outlier_ratio > 1.0f && config.history_segments >= 1 &&
         config.history_segments <= SignalQuality::kMaxHistory && config.min_history_segments >= 1 &&
         config.min_history_segments <= config.history_segments && config.clip_low < config.clip_high &&
         config.max_clipped_fraction >= 0.0f;
}

SignalQuality::SignalQuality(const SignalQualityConfig& config) : config_(config) {
  const float samples = config.segment_ms * config.sample_rate_hz / 1000.0f;
  segment_samples_ = samples < 1.0f ? 1u : static_cast<uint32_t>(samples + 0.5f);
}

void SignalQuality::process(float raw, float filtered) {
  if (in_segment_ == 0) {
    segment_min_ = filtered;
    segment_max_ = filtered;
  }
  if (filtered < segment_min_) segment_min_ = filtered;
  if (filtered > segment_max_) segment_max_ = filtered;
  if (raw <= config_.clip_low || raw >= config_.clip_high) ++clipped_in_segment_;
  ++in_segment_;
  ++sample_index_;
  if (in_segment_ >= segment_samples_) close_segment();
}

void SignalQuality::close_segment() {
  const float amplitude = segment_max_ - segment_min_;
  Segment segment;
  segment.end_ms = static_cast<double>(sample_index_ - 1) * 1000.0 / static_cast<double>(config_.sample_rate_hz);
  segment.clipped =
      static_cast<float>(clipped_in_segment_) > config_.max_clipped_fraction * static_cast<float>(in_segment_);
  if (amplitudes_.size() >= config_.min_history_segments) {
    float scratch[kMaxHistory];
    for (size_t i = 0; i < amplitudes_.size(); ++i) scratch[i] = amplitudes_[i];
    const float envelope = median_in_place(scratch, amplitudes_.size());
    segment.outlier = amplitude > config_.outlier_ratio * envelope || amplitude * config_.outlier_ratio < envelope;
  }
  if (amplitudes_.size() >= config_.history_segments) amplitudes_.pop_front();
  amplitudes_.push_back(amplitude);
  segments_.push_back_overwrite(segment);
  in_segment_ = 0;
  clipped_in_segment_ = 0;
}

QualityStatistics SignalQuality::statistics(double start_ms, double end_ms) const {
  QualityStatistics result;
  for (size_t i = 0; i < segments_.size(); ++i) {
    const Segment& segment = segments_[i];
    if (segment.end_ms <= start_ms || segment.end_ms > end_ms) continue;
    ++result.segments;
    if (segment.outlier) ++result.outliers;
    if (segment.clipped) ++result.clipped;
    if (segment.outlier || segment.clipped) ++result.disturbed;
  }
  return result;
}

}  // namespace alplan::firmware
