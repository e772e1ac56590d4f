// The learners' end-to-end runs behind `alplan perceive ... train|evaluate`
// and the benchmarks: read a dataset in one of the supported layouts, train,
// test, and report in the paper's table form. Plain data in, plain data out.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "perception/cnn_classifier.h"
#include "perception/image_dataset.h"
#include "perception/ppg_simulator.h"
#include "perception/stress_evaluation.h"

namespace alplan::perception {

// Image data by layout: "kdef" (DIR of KDEF files), "folders" (DIR/<class>/),
// "fashion-mnist" (Debian's, or DIR with its four IDX files), "generated"
// (object_image_generator.h; PATH ignored). Throws ImageDatasetError or
// std::invalid_argument naming the layout or path.
ImageDataset read_image_data(const std::string& layout, const std::string& path, bool grey, std::size_t limit = 0);

struct CnnRunOptions {
  CnnArchitecture architecture;
  TrainingOptions training;
  double test_fraction = 0.2;  // the paper's 80/20, when no test set is given
  unsigned seed = 1;
};

struct CnnRunReport {
  TrainingReport training;
  ConfusionMatrix test{std::vector<std::string>{"-", "+"}};
  std::size_t train_samples = 0, test_samples = 0;
  std::size_t parameters = 0;
  double seconds = 0.0;
  nlohmann::json json() const;
};

// Trains a new CNN on `train` and tests it on `test`.
std::pair<CnnClassifier, CnnRunReport> train_and_test_cnn(const ImageDataset& train, const ImageDataset& test,
                                                          const CnnRunOptions& options);
// Splits `data` (stratified, test_fraction) first.
std::pair<CnnClassifier, CnnRunReport> train_and_test_cnn(const ImageDataset& data, const CnnRunOptions& options);

// The simulated stress database and a wristband-like one (the same
// simulator with motion artefacts and more sensor noise: the conditions of
// the paper's Table 2), and what the paper's protocol makes of them.
struct StressSimulationOptions {
  std::size_t subjects = 60;
  double duration_s = 240.0;
  double sample_rate_hz = 50.0;
  std::uint64_t seed = 1;
  std::size_t wristband_subjects = 20;
  MotionArtefacts wristband_motion{3.0, 4.0, 3.0};
  double wristband_noise_sd = 0.08;
  StressFeatureSet features = StressFeatureSet::Paper;
  StressEvaluationOptions evaluation{};
};

struct StressRunReport {
  StressEvaluation evaluation;
  ConfusionMatrix wristband{std::vector<std::string>{"Stressed", "Un-stressed"}};
  // The same windows plus the motion-flagged ones: no artefact rejection.
  ConfusionMatrix wristband_unfiltered{std::vector<std::string>{"Stressed", "Un-stressed"}};
  std::size_t wristband_windows = 0, wristband_rejected = 0;
  double seconds = 0.0;
  nlohmann::json json() const;
};

StressRunReport evaluate_stress_on_simulation(const StressSimulationOptions& options);

// Labelled recordings for training on a user's database: every *.csv file
// below DIR with a label column; the subject is the file's parent folder
// name when the file is in a subfolder, else the file's stem.
std::vector<std::pair<std::string, PpgRecording>> read_recordings(const std::filesystem::path& dir);

// The stress database of the simulator written as CSV files, one folder per
// subject (what read_recordings reads).
void write_simulated_recordings(const std::vector<LabelledRecording>& database, const std::filesystem::path& dir);

}  // namespace alplan::perception
