// A senior's own calm baseline, learned from their first readings. A
// classifier trained on many people mostly learns how fast hearts beat in
// general: a calm senior whose resting rate is high looks stressed to it,
// one whose resting rate is low hides stress. So each senior's first
// `readings` usable windows (they wear the wristband, presumably calm) are
// averaged, and afterwards every reading is moved by the distance between
// that baseline and the classifier's calm centre (the mean of its calm
// training windows) before it is classified: the classifier then judges the
// change from the senior's own calm, not their rate.
//
// Rates (heart rate, IBI) are moved by the difference, variability measures
// (SDNN, RMSSD) scaled by the ratio: stress adds beats per minute but
// multiplies variability down (ppg_simulator.h cites the literature), and a
// senior with little variability to begin with would otherwise look calm
// under any stress. The senior's spread over the calibration is not used to
// rescale: 24 overlapping 30-s windows say little about it, and dividing by a
// small, noisy spread turns noise into alarms.
//
// The limits: a senior already stressed while the baseline is learned has a
// stressed baseline, and that stress is not seen; nor is stress that builds
// up more slowly than the baseline follows (StressCalibration).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "perception/stress/stress_features.h"

namespace alplan::perception {

struct StressCalibration {
  // Usable readings (5 s apart) averaged into the baseline; no decisions
  // before. 0: no baseline, the classifier sees the readings as they are.
  std::size_t readings = 24;
  // Afterwards the baseline follows the senior's readings while they are
  // judged calm, an exponential average over about this many (2.5 min;
  // 0: it stays as learned). A resting rate drifts (posture, meals, the
  // time of day) and a fixed baseline goes stale: on simulated seniors whose
  // rate swings by 4 bpm, a fixed baseline alarmed 16 of 50 calm ones, one
  // following over 30 readings none (perception/README.md). The price:
  // stress that builds up over many minutes is followed, not detected.
  std::size_t follow_readings = 30;
};

class StressBaseline {
 public:
  StressBaseline() = default;
  StressBaseline(StressFeatureSet set, std::size_t readings);

  // One usable reading's feature vector. Returns true when the baseline is
  // complete (this reading may have completed it).
  bool add(const std::vector<float>& features);
  bool complete() const { return seen_ == wanted_; }

  // The features moved from this baseline to `calm_centre`; only once
  // complete.
  std::vector<float> relative(const std::vector<float>& features, const std::vector<float>& calm_centre) const;

  // Moves a complete baseline towards a (calm) reading by 1/readings of the
  // difference.
  void follow(const std::vector<float>& features, std::size_t readings);

  std::size_t seen() const { return seen_; }

 private:
  StressFeatureSet set_ = StressFeatureSet::Paper;
  std::size_t wanted_ = 0, seen_ = 0;
  std::vector<double> mean_;
};

}  // namespace alplan::perception
