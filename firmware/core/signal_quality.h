// Motion-artefact evidence from the PPG itself (the wristband has no
// accelerometer). The signal is cut into segments (2 s: at least one whole
// beat down to 30 bpm); a segment is an outlier when the peak-to-peak
// amplitude of the band-passed signal is more than `outlier_ratio` times, or
// less than 1 / outlier_ratio of, the median amplitude of the segments
// before it (the running robust envelope; the median ignores a minority of
// disturbed segments, and follows a lasting change such as a re-seated
// sensor). Motion on a wrist PPG shows as large swings in the pulse band,
// and a lifted sensor as a collapse of the pulse. A segment is clipped when
// more than max_clipped_fraction of its raw samples reach the ADC's rails.
// Beat plausibility (the rejected fraction) is the third piece of evidence,
// combined in window_features.h.
#pragma once

#include <float.h>
#include <stddef.h>
#include <stdint.h>

#include "ring_buffer.h"

namespace alplan::firmware {

struct SignalQualityConfig {
  float sample_rate_hz = 100.0f;
  float segment_ms = 2000.0f;
  float outlier_ratio = 3.0f;
  uint8_t history_segments = 15;  // the envelope's memory, at most kMaxHistory
  uint8_t min_history_segments = 4;
  float clip_low = -FLT_MAX;   // raw values at or beyond these are clipped
  float clip_high = FLT_MAX;
  float max_clipped_fraction = 0.01f;
};

bool signal_quality_config_is_valid(const SignalQualityConfig& config);

struct QualityStatistics {
  uint16_t segments = 0;  // segments ending in the window
  uint16_t outliers = 0;  // of which amplitude outliers
  uint16_t clipped = 0;   // of which clipped
  uint16_t disturbed = 0; // of which outliers or clipped or both
};

class SignalQuality {
 public:
  static constexpr uint8_t kMaxHistory = 31;
  // Segments remembered for windows: 64 of at least 1 s cover a 60 s window.
  static constexpr size_t kSegmentCapacity = 64;

  explicit SignalQuality(const SignalQualityConfig& config);

  // One raw sample and its band-passed value, sample index 0, 1, ...
  void process(float raw, float filtered);

  // Segments whose last sample's time is in (start_ms, end_ms].
  QualityStatistics statistics(double start_ms, double end_ms) const;

 private:
  struct Segment {
    double end_ms = 0.0;
    bool outlier = false;
    bool clipped = false;
  };
  void close_segment();

  SignalQualityConfig config_;
  uint32_t segment_samples_ = 1;
  uint64_t sample_index_ = 0;
  uint32_t in_segment_ = 0;
  uint32_t clipped_in_segment_ = 0;
  float segment_min_ = 0.0f;
  float segment_max_ = 0.0f;
  RingBuffer<float, kMaxHistory> amplitudes_;
  RingBuffer<Segment, kSegmentCapacity> segments_;
};

}  // namespace alplan::firmware
