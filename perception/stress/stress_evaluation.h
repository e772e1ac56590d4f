// Learning and validating stress detection as the paper's Section 6.1 and
// Tables 1-2 do: the database is split 80% for training and 20% for testing,
// k-fold cross-validation on the training part estimates the model (the
// paper found k = 4 best; here every k of a list is tried and the best mean
// accuracy chooses it), the model is trained on the whole training part and
// the confusion matrix is taken on the test part.
//
// Every split is by subject, never by window: windows of one recording
// overlap and share the subject's resting heart rate, so mixing a subject's
// windows between training and test would measure memory, not detection.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "perception/common/confusion_matrix.h"
#include "perception/stress/ppg_simulator.h"
#include "perception/stress/stress_classifier.h"

namespace alplan::perception {

struct SubjectWindows {
  std::string subject;
  std::vector<StressExample> examples;  // usable windows only
  std::size_t rejected = 0;             // windows dropped as artefacts
  // Of the rejected, those that still had a heart rate (flagged for
  // motion): what a detector without artefact rejection would have used.
  std::vector<StressExample> flagged;
};

// Windows of labelled recordings, grouped by subject (1 = stressed).
std::vector<SubjectWindows> windows_by_subject(const std::vector<LabelledRecording>& recordings,
                                               StressFeatureSet features, const WindowingOptions& windowing = {});

// The same for recordings read from CSV files with a label column: one
// subject per entry (name, recording).
std::vector<SubjectWindows> windows_by_subject(const std::vector<std::pair<std::string, PpgRecording>>& recordings,
                                               StressFeatureSet features, const WindowingOptions& windowing = {});

struct FoldScore {
  int k = 0;
  double mean_accuracy = 0.0;
  double sd_accuracy = 0.0;
};

struct StressEvaluationOptions {
  double test_fraction = 0.2;
  std::vector<int> k_values = {2, 3, 4, 5, 6, 8, 10};
  unsigned seed = 1;
  StressClassifierOptions classifier{};
};

struct StressEvaluation {
  std::vector<FoldScore> cross_validation;  // one per k tried
  int chosen_k = 0;
  ConfusionMatrix test{{"Stressed", "Un-stressed"}};  // the paper's Table 1 rows and columns
  std::vector<std::string> train_subjects, test_subjects;
  std::size_t train_windows = 0, test_windows = 0, rejected_windows = 0;
  StressClassifier model;  // trained on every training subject
};

// Throws std::invalid_argument with too few subjects for the split and the
// largest k.
StressEvaluation evaluate_stress(const std::vector<SubjectWindows>& subjects, const StressEvaluationOptions& options);

// The model's confusion matrix on other subjects (the paper's Table 2: the
// same model on data from the wristband).
// With `include_flagged`, the motion-flagged windows count too (no
// artefact rejection).
ConfusionMatrix stress_confusion(const StressClassifier& model, const std::vector<SubjectWindows>& subjects,
                                 bool include_flagged = false);

}  // namespace alplan::perception
