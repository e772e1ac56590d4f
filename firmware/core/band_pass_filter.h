// The PPG band-pass: a fourth-order Butterworth high-pass (baseline wander,
// respiration, DC) cascaded with a fourth-order Butterworth low-pass (sensor
// noise, the pulse's higher harmonics), each as two biquad sections.
//
// Elgendi et al. (2013, see peak_detector.h) band-pass the PPG at 0.5-8 Hz
// with a second-order Butterworth filter; the default band here is
// 0.5-5 Hz and the order four per side, because on a wristband the
// respiratory baseline (0.2-0.4 Hz) is large against the pulse and needs the
// steeper skirt. Unlike the paper's zero-phase filtfilt this filter is causal:
// peaks come out delayed by its group delay (tens of milliseconds), the same
// delay for every beat, which inter-beat intervals do not see.
#pragma once

#include "biquad.h"

namespace alplan::firmware {

struct BandPassConfig {
  float sample_rate_hz = 100.0f;
  float low_cut_hz = 0.5f;
  float high_cut_hz = 5.0f;
};

// True when 0 < low_cut_hz < high_cut_hz < 0.45 * sample_rate_hz (the
// bilinear transform's pre-warping degrades towards Nyquist).
bool band_is_valid(const BandPassConfig& config);

class BandPassFilter {
 public:
  // Precondition: band_is_valid(config); otherwise the filter passes its
  // input unchanged.
  explicit BandPassFilter(const BandPassConfig& config);

  // Filters one sample. The first sample settles the filter on it (see
  // Biquad::settle), so the output starts near zero instead of ringing.
  float process(float sample);

 private:
  static constexpr int kSections = 4;
  Biquad sections_[kSections];
  bool settled_ = false;
};

}  // namespace alplan::firmware
