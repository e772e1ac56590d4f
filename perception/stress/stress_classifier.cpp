#include "perception/stress/stress_classifier.h"

#include <cmath>

#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

namespace alplan::perception {

struct StressClassifier::Model {
  cv::Ptr<cv::ml::StatModel> model;
};

namespace {

cv::Mat standardised_row(const std::vector<float>& features, const std::vector<float>& mean,
                         const std::vector<float>& deviation) {
  cv::Mat row(1, static_cast<int>(features.size()), CV_32F);
  for (std::size_t i = 0; i < features.size(); ++i) {
    row.at<float>(0, static_cast<int>(i)) = (features[i] - mean[i]) / deviation[i];
  }
  return row;
}

cv::Ptr<cv::ml::StatModel> fit(const cv::Mat& samples, const cv::Mat& labels, const StressClassifierOptions& options) {
  if (options.kind == StressModelKind::Svm) {
    cv::Ptr<cv::ml::SVM> svm = cv::ml::SVM::create();
    svm->setType(cv::ml::SVM::C_SVC);
    svm->setKernel(cv::ml::SVM::RBF);
    const cv::Ptr<cv::ml::TrainData> data = cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, labels);
    svm->trainAuto(data, options.svm_internal_folds);
    return svm;
  }
  cv::Ptr<cv::ml::LogisticRegression> lr = cv::ml::LogisticRegression::create();
  lr->setLearningRate(0.1);
  lr->setIterations(2000);
  lr->setRegularization(cv::ml::LogisticRegression::REG_L2);
  lr->setTrainMethod(cv::ml::LogisticRegression::BATCH);
  cv::Mat float_labels;
  labels.convertTo(float_labels, CV_32F);
  lr->train(samples, cv::ml::ROW_SAMPLE, float_labels);
  return lr;
}

}  // namespace

const char* model_kind_name(StressModelKind kind) { return kind == StressModelKind::Svm ? "svm" : "logistic"; }

StressModelKind model_kind_from_name(const std::string& name) {
  if (name == "svm") return StressModelKind::Svm;
  if (name == "logistic") return StressModelKind::LogisticRegression;
  throw std::invalid_argument("unknown stress model '" + name + "': expected svm or logistic");
}

StressClassifier StressClassifier::train(const std::vector<StressExample>& examples,
                                         const StressClassifierOptions& options) {
  const std::size_t width = feature_names(options.features).size();
  std::size_t per_class[2] = {0, 0};
  for (const StressExample& e : examples) {
    if (e.features.size() != width) {
      throw std::invalid_argument("stress example with " + std::to_string(e.features.size()) + " features, expected " +
                                  std::to_string(width) + " (" + feature_set_name(options.features) + ")");
    }
    if (e.stressed != 0 && e.stressed != 1) throw std::invalid_argument("stress labels are 0 or 1");
    per_class[e.stressed] += 1;
  }
  if (per_class[0] < 2 || per_class[1] < 2) {
    throw std::invalid_argument("training the stress classifier needs at least two examples of each class (got " +
                                std::to_string(per_class[1]) + " stressed, " + std::to_string(per_class[0]) +
                                " un-stressed)");
  }
  StressClassifier c;
  c.options_ = options;
  c.mean_.assign(width, 0.0f);
  c.deviation_.assign(width, 0.0f);
  for (const StressExample& e : examples) {
    for (std::size_t i = 0; i < width; ++i) c.mean_[i] += e.features[i];
  }
  for (float& m : c.mean_) m /= static_cast<float>(examples.size());
  c.calm_centre_.assign(width, 0.0f);
  for (const StressExample& e : examples) {
    if (e.stressed != 0) continue;
    for (std::size_t i = 0; i < width; ++i) c.calm_centre_[i] += e.features[i];
  }
  for (float& m : c.calm_centre_) m /= static_cast<float>(per_class[0]);
  for (const StressExample& e : examples) {
    for (std::size_t i = 0; i < width; ++i) c.deviation_[i] += (e.features[i] - c.mean_[i]) * (e.features[i] - c.mean_[i]);
  }
  for (float& d : c.deviation_) d = std::max(1e-6f, std::sqrt(d / static_cast<float>(examples.size())));

  cv::Mat samples(static_cast<int>(examples.size()), static_cast<int>(width), CV_32F);
  cv::Mat labels(static_cast<int>(examples.size()), 1, CV_32S);
  for (std::size_t n = 0; n < examples.size(); ++n) {
    standardised_row(examples[n].features, c.mean_, c.deviation_).copyTo(samples.row(static_cast<int>(n)));
    labels.at<int>(static_cast<int>(n)) = examples[n].stressed;
  }
  c.model_ = std::make_shared<Model>(Model{fit(samples, labels, options)});
  return c;
}

int StressClassifier::predict(const std::vector<float>& features) const {
  if (features.size() != mean_.size()) {
    throw std::invalid_argument("the stress classifier expects " + std::to_string(mean_.size()) + " features");
  }
  const float answer = model_->model->predict(standardised_row(features, mean_, deviation_));
  return answer >= 0.5f ? 1 : 0;
}

int StressClassifier::predict(const firmware::WindowFeatures& features) const {
  return predict(feature_vector(features, options_.features));
}

void StressClassifier::save(const std::filesystem::path& file) const {
  cv::FileStorage fs(file.string(), cv::FileStorage::WRITE);
  if (!fs.isOpened()) throw std::runtime_error(file.string() + ": cannot write the stress model");
  fs << "format" << "alplan-stress-1";
  fs << "kind" << model_kind_name(options_.kind);
  fs << "features" << feature_set_name(options_.features);
  fs << "mean" << mean_;
  fs << "deviation" << deviation_;
  fs << "calm_mean" << calm_centre_;
  fs << "model" << "{";
  model_->model->write(fs);
  fs << "}";
}

StressClassifier StressClassifier::load(const std::filesystem::path& file) {
  const auto fail = [&](const std::string& what) { throw std::runtime_error(file.string() + ": " + what); };
  if (!std::filesystem::exists(file)) fail("no such file");
  cv::FileStorage fs;
  try {
    fs.open(file.string(), cv::FileStorage::READ);
  } catch (const cv::Exception&) {
    fail("not a stress model (OpenCV cannot read it as YAML, XML or JSON)");
  }
  if (!fs.isOpened() || static_cast<std::string>(fs["format"]) != "alplan-stress-1") {
    fail("not a stress model saved by alplan (format alplan-stress-1)");
  }
  StressClassifier c;
  try {
    c.options_.kind = model_kind_from_name(static_cast<std::string>(fs["kind"]));
    c.options_.features = feature_set_from_name(static_cast<std::string>(fs["features"]));
  } catch (const std::invalid_argument& e) {
    fail(e.what());
  }
  fs["mean"] >> c.mean_;
  fs["deviation"] >> c.deviation_;
  if (!fs["calm_mean"].empty()) fs["calm_mean"] >> c.calm_centre_;
  if (c.mean_.size() != feature_names(c.options_.features).size() || c.deviation_.size() != c.mean_.size()) {
    fail("the standardisation does not match the feature set");
  }
  if (!c.calm_centre_.empty() && c.calm_centre_.size() != c.mean_.size()) fail("the calm mean does not match the feature set");
  cv::Ptr<cv::ml::StatModel> model;
  if (c.options_.kind == StressModelKind::Svm) {
    model = cv::ml::SVM::create();
  } else {
    model = cv::ml::LogisticRegression::create();
  }
  try {
    model->read(fs["model"]);
  } catch (const cv::Exception&) {
    fail("the model section is corrupt");
  }
  if (!model->isTrained()) fail("the model section holds no trained model");
  c.model_ = std::make_shared<Model>(Model{model});
  return c;
}

}  // namespace alplan::perception
