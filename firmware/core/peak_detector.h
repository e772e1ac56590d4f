// Streaming systolic-peak detection in a band-passed PPG, after
//
//   M. Elgendi, I. Norton, M. Brearley, D. Abbott, D. Schuurmans (2013).
//   "Systolic Peak Detection in Acceleration Photoplethysmograms Measured
//   from Emergency Responders in Tropical Conditions". PLoS ONE 8(10):
//   e76585. doi:10.1371/journal.pone.0076585
//
// the method the paper found best of the eight it compared on heat-stressed,
// moving subjects. On the band-passed signal S:
//   1. clip and square: y = max(S, 0)^2, which emphasises systolic waves;
//   2. two moving averages of y centred on each sample: MA_peak over W1 =
//      111 ms (a systolic peak's width) and MA_beat over W2 = 667 ms (a beat);
//   3. blocks of interest are the runs where MA_peak > MA_beat + alpha, with
//      the offset alpha = beta * mean(y), beta = 0.02;
//   4. a block at least W1 wide holds a systolic peak: the maximum of S in it.
//
// Streaming. The paper averages over the whole record and centres its moving
// averages; here S is delayed by W2/2 in a fixed buffer so both averages stay
// centred, and mean(y) becomes an exponential running mean (time constant
// ~10 s, a plain cumulative mean for the first samples). The averages are
// running sums, recomputed from the buffer once per W2 so that float
// round-off cannot accumulate. Two additions, both for a wrist signal: a
// block longer than max_block_ms is rejected (a motion transient, not a
// pulse), which also bounds the reporting delay; and the peak's time is
// refined by a least-squares parabola through the samples within W1/2 of the
// maximum. The refinement matters at low sample rates (40 ms per sample at
// 25 Hz), and at high ones, where noise moves the largest sample of a flat
// top by several samples: every such error enters two intervals, and RMSSD,
// a difference of intervals, doubles it again.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace alplan::firmware {

struct PeakDetectorConfig {
  float sample_rate_hz = 100.0f;
  float peak_window_ms = 111.0f;        // W1
  float beat_window_ms = 667.0f;        // W2
  float offset_fraction = 0.02f;        // beta
  float max_block_ms = 1000.0f;         // longer blocks are artefacts
  float mean_time_constant_s = 10.0f;   // of the running mean(y)
};

// A detected systolic peak, at sample index + fraction (|fraction| <= 1)
// of the filtered signal given to the detector.
struct Peak {
  uint64_t sample_index = 0;
  float fraction = 0.0f;
  float amplitude = 0.0f;  // the filtered signal at the peak
};

// False when the windows do not fit the detector's buffer or are degenerate
// (W1 under three samples, W2 not wider than W1, a block limit under W1).
bool peak_detector_config_is_valid(const PeakDetectorConfig& config);

struct PeakDetection {
  bool detected = false;
  Peak peak{};
};

class PeakDetector {
 public:
  // The delay buffer's size (a power of two); W2 must fit in it, which
  // allows sample rates up to about 760 Hz.
  static constexpr uint32_t kHistoryCapacity = 512;

  explicit PeakDetector(const PeakDetectorConfig& config);

  // An invalid detector (see peak_detector_config_is_valid) never reports a
  // peak.
  bool valid() const { return valid_; }

  // Takes the next band-passed sample (index 0, 1, ...); reports a peak when
  // a block of interest closes. Peaks come out in time order, each at most
  // latency_samples() after its sample index.
  PeakDetection process(float filtered_sample);

  uint32_t latency_samples() const { return half_beat_ + max_block_; }
  uint32_t peak_window_samples() const { return 2 * half_peak_ + 1; }
  uint32_t beat_window_samples() const { return 2 * half_beat_ + 1; }

 private:
  float value_at(int64_t index) const;
  float squared_at(int64_t index) const;
  void recompute_sums();
  float vertex_offset(int64_t index) const;
  PeakDetection evaluate_centre(int64_t centre);

  bool valid_ = false;
  uint32_t half_peak_ = 0;  // W1 = 2 * half_peak_ + 1 samples
  uint32_t half_beat_ = 0;  // W2 = 2 * half_beat_ + 1 samples
  uint32_t max_block_ = 0;  // samples
  float offset_fraction_ = 0.0f;
  float mean_floor_rate_ = 0.0f;

  float history_[kHistoryCapacity]{};
  int64_t newest_ = -1;
  float short_sum_ = 0.0f;
  float long_sum_ = 0.0f;
  uint32_t since_recompute_ = 0;
  float mean_squared_ = 0.0f;
  uint32_t mean_count_ = 0;

  bool in_block_ = false;
  bool refined_ = false;  // block_fraction_ is computed for the current maximum
  int64_t block_start_ = 0;
  int64_t block_max_index_ = 0;
  float block_max_ = 0.0f;
  float block_fraction_ = 0.0f;
};

// Milliseconds from sample 0 to the peak.
double peak_time_ms(const Peak& peak, float sample_rate_hz);

}  // namespace alplan::firmware
