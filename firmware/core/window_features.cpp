#include "window_features.h"

namespace alplan::firmware {

WindowFeatures window_features(const BeatStatistics& beats, const QualityStatistics& quality, uint32_t window_ms,
                               const FeatureThresholds& thresholds) {
  WindowFeatures features;
  features.beat_count = beats.accepted;
  const uint32_t intervals = static_cast<uint32_t>(beats.accepted) + beats.rejected;
  if (intervals > 0) features.rejected_fraction = static_cast<float>(beats.rejected) / static_cast<float>(intervals);

  const uint16_t min_beats = thresholds.min_beats < 2 ? 2 : thresholds.min_beats;
  const float covered_ms = static_cast<float>(beats.accepted) * beats.mean_ibi_ms;
  const bool covered = covered_ms >= thresholds.min_coverage * static_cast<float>(window_ms);
  if (beats.accepted >= min_beats && beats.mean_ibi_ms > 0.0f && covered) {
    features.has_heart_rate = true;
    features.mean_ibi_ms = beats.mean_ibi_ms;
    features.mean_hr_bpm = 60000.0f / beats.mean_ibi_ms;
    features.sdnn_ms = beats.sdnn_ms;
    if (beats.successive_differences >= 2) {
      features.has_rmssd = true;
      features.rmssd_ms = beats.rmssd_ms;
    }
  }

  const bool segments_disturbed =
      quality.segments > 0 && static_cast<float>(quality.disturbed) >
                                  thresholds.max_disturbed_segment_fraction * static_cast<float>(quality.segments);
  features.motion_artefact = segments_disturbed || features.rejected_fraction > thresholds.max_rejected_fraction;
  return features;
}

}  // namespace alplan::firmware
