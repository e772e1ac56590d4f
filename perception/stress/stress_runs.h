// The stress learner's end-to-end runs behind `alplan perceive stress`
// and the benchmarks: the paper's protocol on the simulated database, and
// reading and writing a user's database of CSV recordings. Plain data in,
// plain data out.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "perception/stress/ppg_simulator.h"
#include "perception/stress/stress_evaluation.h"

namespace alplan::perception {

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
