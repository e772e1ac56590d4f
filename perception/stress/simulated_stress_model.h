// A stress classifier trained on the PPG simulator's labelled database
// (perception/stress/ppg_simulator.h), through the wristband core's own windows:
// the default model of `alplan serve` and `alplan deliberate` when no
// trained model file is given, and what the tests and benchmarks use. Deterministic in the spec; a few
// subjects train in well under a second.
#pragma once

#include <cstddef>
#include <cstdint>

#include "perception/stress/stress_classifier.h"

namespace alplan::perception {

struct SimulatedModelSpec {
  std::size_t subjects = 6;
  std::size_t recordings_per_state = 1;
  double recording_s = 120.0;
  double sample_rate_hz = 50.0;
  std::uint64_t seed = 7;
  StressClassifierOptions classifier{StressModelKind::Svm, StressFeatureSet::PaperWithHrv, 5};
};

// Throws std::invalid_argument when the spec yields too few usable windows
// of a class to train on. Kept in the model cache (model_cache.h), keyed by
// the spec: `from_cache` tells whether this run trained it.
StressClassifier train_simulated_stress_classifier(const SimulatedModelSpec& spec, bool* from_cache = nullptr);
// Always trains (the cache's trainer, and runs that measure training).
StressClassifier train_uncached(const SimulatedModelSpec& spec);

}  // namespace alplan::perception
