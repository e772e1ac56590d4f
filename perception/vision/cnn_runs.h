// The CNN's end-to-end runs behind `alplan perceive emotion|objects
// train|evaluate` and the benchmarks: read a dataset in one of the supported
// layouts, train, test, and report in the paper's table form. Plain data in,
// plain data out. (The stress learner's are in stress/stress_runs.h.)
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "perception/vision/cnn_classifier.h"
#include "perception/vision/image_dataset.h"

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

}  // namespace alplan::perception
