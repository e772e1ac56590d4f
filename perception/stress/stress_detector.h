// Stress detection (the paper's layer 1): readings from a senior's
// wristband come in one by one; the detector says whether the senior is
// stressed, and when that changes (a stress event, which wakes the rest of
// the deliberation: emotion recognition, goal generation, planning).
//
// `ClassifierStressDetector` classifies each usable window with the trained
// StressClassifier and, as the paper's Discussion proposes against motion
// noise, decides on the average of the last `smoothing_readings` votes:
// stressed when at least `enter_fraction` of them say so, calm again when at
// most `leave_fraction` do (hysteresis, so one noisy window does not toggle
// the state). Windows flagged for motion or without a heart rate are not
// voted on; they are counted.
//
// By default each senior's first usable readings are a calibration: they
// make the senior's own calm baseline (stress_baseline.h says why) and are
// not decided on; later readings are classified relative to it. Without it
// (`StressCalibration{0}`) calm seniors whose resting rate is high raise
// false stress events (perception/README.md, "False alarms", measures both).
#pragma once

#include <cstddef>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "firmware/core/window_features.h"
#include "perception/stress/stress_baseline.h"
#include "perception/stress/stress_classifier.h"

namespace alplan::perception {

struct StressState {
  bool stressed = false;
  double stressed_fraction = 0.0;  // of the votes in the current average
  std::size_t votes = 0;           // usable readings in the average
  std::size_t rejected = 0;        // readings not voted on so far (motion, no rate)
  bool calibrating = false;        // the senior's baseline is still being learned: no decision yet
};

struct StressObservation {
  StressState state;
  bool changed = false;  // this reading flipped the decision: a stress event
};

class StressDetector {
 public:
  virtual ~StressDetector() = default;
  // One reading of a senior's wristband, in time order per senior.
  virtual StressObservation observe(const std::string& senior, const firmware::WindowFeatures& reading) = 0;
  // The current decision for a senior; nothing before any reading.
  virtual std::optional<StressState> state(const std::string& senior) const = 0;

  // What the detector remembers of one senior (opaque; null when it knows
  // nothing of them), and putting that back. The signal service detects
  // inside a transaction; when the commit fails the readings are not stored
  // and will be re-sent, so the detector must forget it saw them.
  using Memory = std::shared_ptr<const void>;
  virtual Memory remember(const std::string& senior) const = 0;
  virtual void restore(const std::string& senior, const Memory& memory) = 0;
};

struct StressSmoothing {
  std::size_t smoothing_readings = 6;  // 6 readings 5 s apart: the last 55 s
  std::size_t min_votes = 3;           // decide nothing with fewer usable readings
  double enter_fraction = 0.6;
  double leave_fraction = 0.3;
};

class ClassifierStressDetector : public StressDetector {
 public:
  // Throws std::invalid_argument for inconsistent smoothing, or a
  // calibration with a model that keeps no calm centre (an old model file).
  ClassifierStressDetector(StressClassifier classifier, const StressSmoothing& smoothing,
                           const StressCalibration& calibration = {});

  StressObservation observe(const std::string& senior, const firmware::WindowFeatures& reading) override;
  std::optional<StressState> state(const std::string& senior) const override;
  Memory remember(const std::string& senior) const override;
  void restore(const std::string& senior, const Memory& memory) override;

 private:
  struct Senior {
    std::deque<int> votes;
    StressState state;
    StressBaseline baseline;
  };
  Senior& record_of(const std::string& name);

  StressClassifier classifier_;
  StressSmoothing smoothing_;
  StressCalibration calibration_;
  std::map<std::string, Senior> seniors_;
};

}  // namespace alplan::perception
