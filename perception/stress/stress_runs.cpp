#include "perception/stress/stress_runs.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace alplan::perception {
namespace fs = std::filesystem;
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

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
