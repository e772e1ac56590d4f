// The features one reading carries, computed over a sliding window of beats
// (30 s by default, see wristband_core.h). Averaging over a window is the
// Babli et al. paper's own answer to motion noise on the wristband; the
// motion flag says when even the window is not to be trusted.
#pragma once

#include <stdint.h>

#include "beat_window.h"
#include "signal_quality.h"

namespace alplan::firmware {

struct WindowFeatures {
  // The rate fields (mean_hr_bpm, mean_ibi_ms, sdnn_ms) are meaningful only
  // with at least min_beats accepted intervals that together cover at least
  // min_coverage of the window; rmssd_ms only with at least two successive
  // differences besides. Otherwise they are 0 and the flags false (and the
  // JSON says null): under heavy motion a window says "unknown" rather than
  // a rate made from a few surviving intervals.
  bool has_heart_rate = false;
  bool has_rmssd = false;
  float mean_hr_bpm = 0.0f;  // 60000 / mean IBI: the rate of the mean interval
  float mean_ibi_ms = 0.0f;
  float sdnn_ms = 0.0f;
  float rmssd_ms = 0.0f;
  uint16_t beat_count = 0;         // accepted intervals in the window
  float rejected_fraction = 0.0f;  // rejected / (accepted + rejected), 0 with neither
  bool motion_artefact = false;
};

struct FeatureThresholds {
  uint16_t min_beats = 5;
  float min_coverage = 0.5f;  // accepted intervals' total / window length
  // The window is flagged as disturbed by motion when more than this
  // fraction of its intervals were rejected...
  float max_rejected_fraction = 0.2f;
  // ...or of its signal segments were amplitude outliers or clipped.
  float max_disturbed_segment_fraction = 0.1f;
};

WindowFeatures window_features(const BeatStatistics& beats, const QualityStatistics& quality, uint32_t window_ms,
                               const FeatureThresholds& thresholds);

}  // namespace alplan::firmware
