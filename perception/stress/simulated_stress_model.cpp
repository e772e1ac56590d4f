#include "perception/stress/simulated_stress_model.h"

#include <vector>

#include "perception/stress/ppg_simulator.h"
#include "perception/stress/stress_features.h"

namespace alplan::perception {

StressClassifier train_simulated_stress_classifier(const SimulatedModelSpec& spec) {
  DatabaseSpec database;
  database.subjects = spec.subjects;
  database.recordings_per_state = spec.recordings_per_state;
  database.conditions.duration_s = spec.recording_s;
  database.conditions.sample_rate_hz = spec.sample_rate_hz;
  database.seed = spec.seed;
  std::vector<StressExample> examples;
  for (const LabelledRecording& item : generate_labelled_database(database)) {
    for (const StressWindow& w : stress_windows(item.simulated.recording)) {
      if (!w.usable || w.label < 0) continue;
      examples.push_back({feature_vector(w.features, spec.classifier.features), w.label});
    }
  }
  return StressClassifier::train(examples, spec.classifier);
}

}  // namespace alplan::perception
