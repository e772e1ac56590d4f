#include "perception/vision/cnn_runs.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "perception/vision/object_image_generator.h"

namespace alplan::perception {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

nlohmann::json training_json(const TrainingReport& r) {
  nlohmann::json epochs = nlohmann::json::array();
  for (const EpochReport& e : r.epochs) {
    epochs.push_back({{"epoch", e.epoch},
                      {"train_loss", e.train_loss},
                      {"validation_loss", e.validation_loss},
                      {"validation_accuracy", e.validation_accuracy},
                      {"seconds", e.seconds}});
  }
  return {{"epochs", epochs}, {"best_epoch", r.best_epoch}, {"stopped_early", r.stopped_early}};
}

}  // namespace

ImageDataset read_image_data(const std::string& layout, const std::string& path, bool grey, std::size_t limit) {
  ReadOptions options;
  options.grey = grey;
  options.limit = limit;
  if (layout == "kdef") return read_kdef(path, options);
  if (layout == "folders") return read_class_folders(path, options);
  if (layout == "fashion-mnist") {
    return path.empty() ? read_fashion_mnist(true, options) : read_fashion_mnist(true, options, path);
  }
  if (layout == "generated") {
    ObjectImageOptions generated;
    if (limit) generated.per_class = std::max<std::size_t>(1, limit / drawable_object_classes().size());
    ImageDataset data = generate_object_images(generated);
    if (grey) {
      for (LabelledImage& s : data.samples) cv::cvtColor(s.image, s.image, cv::COLOR_BGR2GRAY);
    }
    return data;
  }
  throw std::invalid_argument("unknown image layout '" + layout + "': expected kdef, folders, fashion-mnist or generated");
}

nlohmann::json CnnRunReport::json() const {
  return {{"training", training_json(training)}, {"test", test.json()},          {"train_samples", train_samples},
          {"test_samples", test_samples},        {"parameters", parameters}, {"seconds", seconds}};
}

std::pair<CnnClassifier, CnnRunReport> train_and_test_cnn(const ImageDataset& train, const ImageDataset& test,
                                                          const CnnRunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  CnnClassifier model(train.classes, options.architecture, options.seed);
  CnnRunReport report;
  report.training = model.train(train, options.training);
  report.test = model.evaluate(test);
  report.train_samples = train.samples.size();
  report.test_samples = test.samples.size();
  report.parameters = model.parameter_count();
  report.seconds = seconds_since(start);
  return {std::move(model), report};
}

std::pair<CnnClassifier, CnnRunReport> train_and_test_cnn(const ImageDataset& data, const CnnRunOptions& options) {
  const DatasetSplit split = split_dataset(data, options.test_fraction, options.seed);
  return train_and_test_cnn(split.train, split.test, options);
}

}  // namespace alplan::perception
