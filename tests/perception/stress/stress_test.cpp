#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "perception/stress/ppg_simulator.h"
#include "perception/stress/stress_detector.h"
#include "perception/stress/stress_evaluation.h"
#include "perception/stress/stress_features.h"

using namespace alplan::perception;

namespace {

DatabaseSpec small_database(std::size_t subjects, std::uint64_t seed) {
  DatabaseSpec spec;
  spec.subjects = subjects;
  spec.recordings_per_state = 1;
  spec.conditions.duration_s = 150.0;
  spec.conditions.sample_rate_hz = 50.0;
  spec.seed = seed;
  return spec;
}

std::vector<StressExample> pooled(const std::vector<SubjectWindows>& subjects) {
  std::vector<StressExample> all;
  for (const SubjectWindows& s : subjects) all.insert(all.end(), s.examples.begin(), s.examples.end());
  return all;
}

}  // namespace

TEST_CASE("stress windows come from the wristband core, with the recording's labels") {
  PpgSimulator simulator(3);
  SubjectProfile calm = simulator.random_subject();
  RecordingConditions conditions;
  conditions.duration_s = 90.0;
  SimulatedRecording r = simulator.simulate(calm, conditions);
  r.recording.label.assign(r.recording.size(), 1);
  const std::vector<StressWindow> windows = stress_windows(r.recording);
  // 30 s windows every 5 s over 90 s, less the core's reporting latency.
  REQUIRE(windows.size() >= 10);
  REQUIRE(windows.size() <= 13);
  for (const StressWindow& w : windows) {
    CHECK(w.label == 1);
    CHECK(w.usable);
    CHECK(w.features.mean_hr_bpm == Approx(true_mean_hr_bpm(r.beat_times_s, w.end_s - 30.0, w.end_s)).margin(2.0));
  }
  CHECK(feature_vector(windows.front().features, StressFeatureSet::Paper).size() == 2);
  CHECK(feature_vector(windows.front().features, StressFeatureSet::PaperWithHrv).size() == 4);
  CHECK_THROWS_AS(stress_windows(r.recording, {30.0, 0.0}), std::invalid_argument);
}

TEST_CASE("motion-disturbed windows are rejected as artefacts") {
  DatabaseSpec spec = small_database(2, 5);
  spec.conditions.motion.bursts_per_minute = 6;
  spec.conditions.motion.strength = 6;
  const std::vector<SubjectWindows> noisy = windows_by_subject(generate_labelled_database(spec), StressFeatureSet::Paper);
  const std::vector<SubjectWindows> clean =
      windows_by_subject(generate_labelled_database(small_database(2, 5)), StressFeatureSet::Paper);
  std::size_t noisy_rejected = 0, clean_rejected = 0;
  for (const auto& s : noisy) noisy_rejected += s.rejected;
  for (const auto& s : clean) clean_rejected += s.rejected;
  CHECK(clean_rejected == 0);
  CHECK(noisy_rejected > 0);
}

TEST_CASE("the classifier separates stressed from calm subjects it has not seen, and survives a save") {
  const auto train = windows_by_subject(generate_labelled_database(small_database(16, 11)), StressFeatureSet::Paper);
  const auto unseen = windows_by_subject(generate_labelled_database(small_database(6, 12)), StressFeatureSet::Paper);
  for (StressModelKind kind : {StressModelKind::LogisticRegression, StressModelKind::Svm}) {
    StressClassifierOptions options;
    options.kind = kind;
    const StressClassifier model = StressClassifier::train(pooled(train), options);
    const ConfusionMatrix matrix = stress_confusion(model, unseen);
    INFO(model_kind_name(kind) << "\n" << matrix.markdown());
    CHECK(matrix.accuracy() > 0.7);  // chance is 0.5: the two classes are equally frequent

    const auto file = std::filesystem::temp_directory_path() / (std::string("alplan-stress-") + model_kind_name(kind) + ".yml");
    model.save(file);
    const StressClassifier loaded = StressClassifier::load(file);
    CHECK(stress_confusion(loaded, unseen).json()["counts"] == matrix.json()["counts"]);
  }
}

TEST_CASE("bad stress training data and foreign model files are refused with a reason") {
  CHECK_THROWS_WITH(StressClassifier::train({{{70.f, 850.f}, 1}, {{72.f, 830.f}, 0}}, {}),
                    Catch::Contains("at least two examples of each class"));
  CHECK_THROWS_WITH(StressClassifier::train({{{70.f}, 1}}, {}), Catch::Contains("expected 2 (paper)"));
  const auto file = std::filesystem::temp_directory_path() / "alplan-not-a-model.yml";
  std::ofstream(file) << "%YAML:1.0\nformat: something-else\n";
  CHECK_THROWS_WITH(StressClassifier::load(file), Catch::Contains("not a stress model saved by alplan"));
  CHECK_THROWS_WITH(StressClassifier::load(file.string() + ".missing"), Catch::Contains("no such file"));
  CHECK_THROWS_AS(model_kind_from_name("forest"), std::invalid_argument);
  CHECK_THROWS_AS(feature_set_from_name("ecg"), std::invalid_argument);
}

TEST_CASE("the paper's protocol: split by subject, k chosen by cross-validation, Table 1 on the test subjects") {
  const auto subjects = windows_by_subject(generate_labelled_database(small_database(20, 21)), StressFeatureSet::Paper);
  StressEvaluationOptions options;
  options.k_values = {2, 4, 5};
  const StressEvaluation e = evaluate_stress(subjects, options);
  CHECK(e.test_subjects.size() == 4);
  CHECK(e.train_subjects.size() == 16);
  for (const std::string& s : e.test_subjects) {
    CHECK(std::find(e.train_subjects.begin(), e.train_subjects.end(), s) == e.train_subjects.end());
  }
  REQUIRE(e.cross_validation.size() == 3);
  double best = 0;
  for (const FoldScore& f : e.cross_validation) best = std::max(best, f.mean_accuracy);
  for (const FoldScore& f : e.cross_validation) {
    if (f.k == e.chosen_k) CHECK(f.mean_accuracy == best);
  }
  CHECK(e.test.total() == e.test_windows);
  CHECK(e.test.classes() == std::vector<std::string>{"Stressed", "Un-stressed"});
  CHECK(e.test.accuracy() > 0.7);
  CHECK_THROWS_WITH(evaluate_stress(std::vector<SubjectWindows>(subjects.begin(), subjects.begin() + 4), options),
                    Catch::Contains("too few"));
}

TEST_CASE("the stress detector votes over a window of readings and reports changes once") {
  const auto train = windows_by_subject(generate_labelled_database(small_database(12, 31)), StressFeatureSet::Paper);
  // Without a baseline: the voting is what is tested here (stress_baseline_test.cpp tests the baseline).
  ClassifierStressDetector detector(StressClassifier::train(pooled(train), {}), StressSmoothing{}, StressCalibration{0});
  CHECK_FALSE(detector.state("senior1").has_value());

  alplan::firmware::WindowFeatures calm;
  calm.has_heart_rate = true;
  calm.mean_hr_bpm = 62.0f;
  calm.mean_ibi_ms = 60000.0f / 62.0f;
  alplan::firmware::WindowFeatures racing = calm;
  racing.mean_hr_bpm = 105.0f;
  racing.mean_ibi_ms = 60000.0f / 105.0f;
  alplan::firmware::WindowFeatures shaken = racing;
  shaken.motion_artefact = true;

  int events = 0;
  for (int i = 0; i < 6; ++i) events += detector.observe("senior1", calm).changed;
  CHECK(events == 0);
  CHECK_FALSE(detector.state("senior1")->stressed);
  // Motion-flagged readings are not believed, however fast the heart.
  for (int i = 0; i < 6; ++i) events += detector.observe("senior1", shaken).changed;
  CHECK(events == 0);
  CHECK(detector.state("senior1")->rejected == 6);
  for (int i = 0; i < 6; ++i) events += detector.observe("senior1", racing).changed;
  CHECK(events == 1);
  CHECK(detector.state("senior1")->stressed);
  // Another senior is judged on their own readings.
  detector.observe("senior2", calm);
  CHECK(detector.state("senior2")->votes == 1);
  for (int i = 0; i < 6; ++i) events += detector.observe("senior1", calm).changed;
  CHECK(events == 2);
  CHECK_FALSE(detector.state("senior1")->stressed);
  CHECK_THROWS_AS(ClassifierStressDetector(StressClassifier::train(pooled(train), {}), StressSmoothing{4, 5, 0.6, 0.3}),
                  std::invalid_argument);
}
