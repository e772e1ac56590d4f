#include "perception/learning_runs.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

#include "perception/object_image_generator.h"

namespace alplan::perception {
namespace fs = std::filesystem;
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

nlohmann::json StressRunReport::json() const {
  nlohmann::json folds = nlohmann::json::array();
  for (const FoldScore& f : evaluation.cross_validation) {
    folds.push_back({{"k", f.k}, {"mean_accuracy", f.mean_accuracy}, {"sd_accuracy", f.sd_accuracy}});
  }
  return {{"cross_validation", folds},
          {"chosen_k", evaluation.chosen_k},
          {"train_subjects", evaluation.train_subjects.size()},
          {"test_subjects", evaluation.test_subjects},
          {"train_windows", evaluation.train_windows},
          {"test_windows", evaluation.test_windows},
          {"rejected_windows", evaluation.rejected_windows},
          {"dataset", evaluation.test.json()},
          {"wristband", wristband.json()},
          {"wristband_without_artefact_rejection", wristband_unfiltered.json()},
          {"wristband_windows", wristband_windows},
          {"wristband_rejected", wristband_rejected},
          {"seconds", seconds}};
}

StressRunReport evaluate_stress_on_simulation(const StressSimulationOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  DatabaseSpec spec;
  spec.subjects = options.subjects;
  spec.recordings_per_state = 1;
  spec.conditions.duration_s = options.duration_s;
  spec.conditions.sample_rate_hz = options.sample_rate_hz;
  spec.seed = options.seed;
  const std::vector<SubjectWindows> subjects = windows_by_subject(generate_labelled_database(spec), options.features);
  StressEvaluationOptions evaluation = options.evaluation;
  evaluation.classifier.features = options.features;
  StressRunReport report;
  report.evaluation = evaluate_stress(subjects, evaluation);

  DatabaseSpec wristband = spec;
  wristband.subjects = options.wristband_subjects;
  wristband.seed = options.seed + 1000;  // other people
  wristband.conditions.motion = options.wristband_motion;
  wristband.conditions.noise_sd = options.wristband_noise_sd;
  const std::vector<SubjectWindows> worn = windows_by_subject(generate_labelled_database(wristband), options.features);
  report.wristband = stress_confusion(report.evaluation.model, worn);
  report.wristband_unfiltered = stress_confusion(report.evaluation.model, worn, true);
  for (const SubjectWindows& s : worn) {
    report.wristband_windows += s.examples.size();
    report.wristband_rejected += s.rejected;
  }
  report.seconds = seconds_since(start);
  return report;
}

std::vector<std::pair<std::string, PpgRecording>> read_recordings(const fs::path& dir) {
  if (!fs::is_directory(dir)) throw std::invalid_argument(dir.string() + ": not a folder of CSV recordings");
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".csv") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  if (files.empty()) throw std::invalid_argument(dir.string() + ": no .csv recordings below this folder");
  std::vector<std::pair<std::string, PpgRecording>> out;
  for (const fs::path& f : files) {
    const std::string subject = f.parent_path() == dir ? f.stem().string() : f.parent_path().filename().string();
    out.emplace_back(subject, read_ppg_csv_file(f));
    if (!out.back().second.has_labels()) {
      throw std::invalid_argument(f.string() + ": no label column (time,ppg,label) to learn from");
    }
  }
  return out;
}

void write_simulated_recordings(const std::vector<LabelledRecording>& database, const fs::path& dir) {
  std::size_t n = 0;
  for (const LabelledRecording& r : database) {
    fs::create_directories(dir / r.subject_id);
    write_ppg_csv_file(dir / r.subject_id / ((r.stressed ? "stressed-" : "calm-") + std::to_string(n++) + ".csv"),
                       r.simulated.recording);
  }
}

}  // namespace alplan::perception
