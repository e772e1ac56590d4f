#include "perception/stress/simulated_stress_model.h"

#include <sstream>
#include <vector>

#include "perception/common/model_cache.h"

#include "perception/stress/ppg_simulator.h"
#include "perception/stress/stress_features.h"

namespace alplan::perception {

namespace {

// What the trained model depends on. Bump the version when the simulator,
// the features or the training change what is learned.
std::string cache_key(const SimulatedModelSpec& spec) {
  constexpr int kVersion = 1;
  std::ostringstream key;
  key.precision(17);
  key << "simulated-stress v" << kVersion << " subjects " << spec.subjects << " per-state "
      << spec.recordings_per_state << " seconds " << spec.recording_s << " hz " << spec.sample_rate_hz << " seed "
      << spec.seed << " kind " << static_cast<int>(spec.classifier.kind) << " features "
      << static_cast<int>(spec.classifier.features) << " folds " << spec.classifier.svm_internal_folds;
  return key.str();
}

}  // namespace

StressClassifier train_simulated_stress_classifier(const SimulatedModelSpec& spec, bool* from_cache) {
  return cached_model<StressClassifier>(
      model_cache_name("stress-classifier", cache_key(spec), ".yml"),
      [&] { return train_uncached(spec); }, [](const std::filesystem::path& f) { return StressClassifier::load(f); },
      [](const StressClassifier& m, const std::filesystem::path& f) { m.save(f); }, from_cache);
}

StressClassifier train_uncached(const SimulatedModelSpec& spec) {
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
