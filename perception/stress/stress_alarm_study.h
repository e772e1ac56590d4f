// How often the stress detector cries wolf, and how soon it sees real
// stress: simulated seniors wear the wristband for a long while, half of
// them calm throughout, half calm and then stressed, and detectors
// (features, with or without a per-senior baseline) are run over the same
// readings. A senior is one seed of the PPG simulator; the calm and the
// stressed senior of a seed are the same person (the same resting profile),
// so each detector meets everybody twice.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "perception/stress/ppg_simulator.h"
#include "perception/stress/simulated_stress_model.h"
#include "perception/stress/stress_classifier.h"
#include "perception/stress/stress_detector.h"

namespace alplan::perception {

// The simulator's senior of `seed` (PpgSimulator(seed).random_subject()):
// calm for calm_s, then, when stressed_s > 0, stressed (the seed's own
// stress response) for stressed_s, as one recording. The simulator's
// subject keeps one resting rate; a real one's drifts (posture, activity,
// meals): with drift_bpm > 0 the resting rate swings by up to that much,
// slowly, so that a baseline learned at the start goes stale.
PpgRecording simulated_senior(std::uint64_t seed, double calm_s, double stressed_s,
                              const RecordingConditions& conditions, double drift_bpm = 0.0);

struct AlarmStudyDetector {
  StressFeatureSet features = StressFeatureSet::Paper;
  StressCalibration calibration{0, 0};  // readings 0: no per-senior baseline
  std::string name() const;
};

struct AlarmStudyOptions {
  std::size_t seniors = 20;  // calm ones, and as many stressed ones
  std::uint64_t first_seed = 1;
  double minutes = 25.0;
  double onset_minutes = 10.0;  // the stressed seniors are calm until then
  RecordingConditions conditions{50.0, 0.0, 0.03, 0.5, 0.0, {}};  // duration set per senior
  double drift_bpm = 0.0;  // see simulated_senior
  // The models: trained on the simulator's database, as `deliberate` does,
  // from seeds no senior here has.
  // (training.classifier.features is set per detector.)
  SimulatedModelSpec training{24, 1, 150.0, 50.0, 1000, StressClassifierOptions{}};
  StressSmoothing smoothing{};
  std::vector<AlarmStudyDetector> detectors = {
      {StressFeatureSet::Paper, {0, 0}},   {StressFeatureSet::PaperWithHrv, {0, 0}},
      {StressFeatureSet::Paper, {24, 0}},  {StressFeatureSet::PaperWithHrv, {24, 0}},
      {StressFeatureSet::Paper, {24, 30}}, {StressFeatureSet::PaperWithHrv, {24, 30}}};
};

struct AlarmStudyRow {
  AlarmStudyDetector detector;
  std::size_t calm_seniors = 0, calm_alarmed = 0;  // calm seniors with at least one stress event
  std::size_t calm_events = 0;
  double calm_hours = 0.0;
  std::size_t stressed_seniors = 0, detected = 0;  // an event after the onset
  std::size_t early_alarmed = 0;                   // stressed seniors with an event before the onset
  std::vector<double> latencies_s;                 // onset to the first event after it, per detected senior
  std::vector<std::uint64_t> alarmed_seeds;        // the calm seniors alarmed
  double events_per_hour() const { return calm_hours > 0 ? static_cast<double>(calm_events) / calm_hours : 0.0; }
};

struct AlarmStudyReport {
  AlarmStudyOptions options;
  std::vector<AlarmStudyRow> rows;
  double seconds = 0.0;
  std::string markdown() const;
  nlohmann::json json() const;
};

// Throws std::invalid_argument when the onset is not inside the recording.
AlarmStudyReport run_alarm_study(const AlarmStudyOptions& options);

}  // namespace alplan::perception
