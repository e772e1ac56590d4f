// Runs the wristband core over simulated recordings and measures it against
// the simulator's true beats: what the firmware tests share.
#pragma once

#include <cstddef>
#include <vector>

#include "firmware/core/wristband_core.h"
#include "perception/stress/ppg_simulator.h"

namespace alplan::test {

struct CoreRun {
  std::vector<firmware::Reading> readings;
  std::vector<double> peak_times_s;  // every peak the detector reported
  std::vector<firmware::BeatEvent> beats;
};

CoreRun run_core(const firmware::CoreConfig& config, const std::vector<double>& ppg);

// Detected peaks against true beats within [start_s, end_s]: a detection
// matches an unmatched true beat within tolerance_s of it after the median
// lag (the band-pass filter's group delay) is taken off.
struct BeatMatch {
  std::size_t true_positives = 0;
  std::size_t false_positives = 0;
  std::size_t false_negatives = 0;
  double lag_s = 0.0;
  double sensitivity() const;
  double precision() const;
};

BeatMatch match_beats(const std::vector<double>& true_beats_s, const std::vector<double>& detected_s,
                      double tolerance_s, double start_s, double end_s);

// The median delay of detected peaks after the true beats near them: the
// band-pass filter's group delay (0-70 ms, depending on the heart rate).
double detection_lag_s(const std::vector<double>& true_beats_s, const std::vector<double>& detected_s);

// Each reading's mean HR against the true mean HR of the beats it covers:
// a reading covers the peaks detected in (t - window, t] (its timestamp t
// taken as seconds from the recording's start), which are the true beats of
// that window moved back by the detection lag.
struct HeartRateErrors {
  std::vector<double> absolute_bpm;  // of the readings that have a rate
  std::size_t readings = 0;
  std::size_t without_rate = 0;
  double mean() const;
  double max() const;
  double percentile(double fraction) const;
};

HeartRateErrors heart_rate_errors(const CoreRun& run, const std::vector<double>& true_beats_s);

// The interval statistics of the true beats in (start_s, end_s], the way the
// core computes them (intervals ending in the window); shift the window by
// detection_lag_s() to compare with a reading.
struct TrueVariability {
  double sdnn_ms = 0.0;
  double rmssd_ms = 0.0;
};
TrueVariability true_variability(const std::vector<double>& true_beats_s, double start_s, double end_s);

}  // namespace alplan::test
