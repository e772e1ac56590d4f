// The binary stress classifier (stressed / un-stressed) of the paper's
// "learning stress" module (Section 6.1), on the wristband's window
// features. OpenCV's ml module does the learning: logistic regression (the
// default: on the simulated database it is as accurate as the SVM and
// trains in a fraction of the time), or an RBF support vector machine whose
// C and gamma OpenCV's trainAuto picks by its own internal cross-validation.
// Features are standardised with the training set's mean and deviation,
// which the model file keeps.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "perception/stress/stress_features.h"

namespace alplan::perception {

enum class StressModelKind { Svm, LogisticRegression };

const char* model_kind_name(StressModelKind kind);
StressModelKind model_kind_from_name(const std::string& name);  // "svm", "logistic"

struct StressClassifierOptions {
  StressModelKind kind = StressModelKind::LogisticRegression;
  StressFeatureSet features = StressFeatureSet::Paper;
  int svm_internal_folds = 5;  // trainAuto's own cross-validation for C and gamma
};

// One training example: a feature vector (feature_vector(...)) and 1 for
// stressed, 0 for un-stressed.
struct StressExample {
  std::vector<float> features;
  int stressed = 0;
};

class StressClassifier {
 public:
  // Throws std::invalid_argument with fewer than two examples of each class
  // or vectors of the wrong length.
  static StressClassifier train(const std::vector<StressExample>& examples, const StressClassifierOptions& options);

  // 1 stressed, 0 un-stressed.
  int predict(const std::vector<float>& features) const;
  int predict(const firmware::WindowFeatures& features) const;

  void save(const std::filesystem::path& file) const;
  // Throws std::runtime_error naming the file on a missing or foreign file.
  static StressClassifier load(const std::filesystem::path& file);

  const StressClassifierOptions& options() const { return options_; }
  // The mean of the calm training windows (raw features): where a senior's
  // own calm baseline is moved to (stress_baseline.h). Empty for a model
  // file saved before it was kept.
  const std::vector<float>& calm_centre() const { return calm_centre_; }

 private:
  struct Model;
  StressClassifierOptions options_;
  std::vector<float> mean_, deviation_, calm_centre_;
  std::shared_ptr<const Model> model_;  // immutable once trained: copies share it
};

}  // namespace alplan::perception
