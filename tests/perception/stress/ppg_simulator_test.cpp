#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "perception/stress/ppg_simulator.h"

using namespace alplan::perception;

namespace {

double mean(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double rmssd_ms(const std::vector<double>& beats) {
  double sum = 0.0;
  for (std::size_t i = 2; i < beats.size(); ++i) {
    const double d = 1000.0 * ((beats[i] - beats[i - 1]) - (beats[i - 1] - beats[i - 2]));
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(beats.size() - 2));
}

}  // namespace

TEST_CASE("the same seed gives the same recording, another seed another") {
  RecordingConditions conditions;
  conditions.duration_s = 20.0;
  conditions.motion.bursts_per_minute = 6.0;
  PpgSimulator a(42);
  PpgSimulator b(42);
  PpgSimulator c(43);
  const SimulatedRecording ra = a.simulate(a.random_subject(), conditions);
  const SimulatedRecording rb = b.simulate(b.random_subject(), conditions);
  const SimulatedRecording rc = c.simulate(c.random_subject(), conditions);
  CHECK(ra.recording.ppg == rb.recording.ppg);
  CHECK(ra.beat_times_s == rb.beat_times_s);
  CHECK(ra.motion_bursts.size() == rb.motion_bursts.size());
  CHECK(ra.recording.ppg != rc.recording.ppg);
}

TEST_CASE("a recording has the asked rate, length and heart rate, and its beats are its peaks") {
  PpgSimulator simulator(1);
  SubjectProfile subject;
  subject.resting_hr_bpm = 84.0;
  RecordingConditions conditions;
  conditions.sample_rate_hz = 128.0;
  conditions.duration_s = 60.0;
  conditions.noise_sd = 0.0;
  conditions.baseline_wander = 0.0;
  const SimulatedRecording r = simulator.simulate(subject, conditions);
  CHECK(r.recording.size() == 128 * 60);
  CHECK(r.recording.sample_rate_hz() == Approx(128.0));
  CHECK(true_mean_hr_bpm(r.beat_times_s, 0.0, 60.0) == Approx(84.0).margin(2.0));
  CHECK(r.motion_bursts.empty());
  // Without noise and wander, the largest sample within 0.2 s of each true
  // beat lies within two samples of it (the dicrotic wave pulls it a little).
  for (double beat : r.beat_times_s) {
    if (beat < 0.3 || beat > 59.7) continue;
    const auto centre = static_cast<std::size_t>(std::lround(beat * 128.0));
    std::size_t best = centre - 25;
    for (std::size_t i = centre - 25; i <= centre + 25; ++i) {
      if (r.recording.ppg[i] > r.recording.ppg[best]) best = i;
    }
    CHECK(std::abs(static_cast<double>(best) / 128.0 - beat) <= 2.0 / 128.0);
  }
}

TEST_CASE("motion bursts come at the asked rate and disturb the signal strongly") {
  PpgSimulator simulator(9);
  RecordingConditions quiet;
  quiet.duration_s = 600.0;
  RecordingConditions moving = quiet;
  moving.motion = {4.0, 5.0, 3.0};
  const SubjectProfile subject;
  const SimulatedRecording still = PpgSimulator(9).simulate(subject, quiet);
  const SimulatedRecording moved = PpgSimulator(9).simulate(subject, moving);
  CHECK(moved.motion_bursts.size() >= 25);  // Poisson with mean about 4 * 10 * (1 - share of burst time)
  CHECK(moved.motion_bursts.size() <= 50);
  double largest_difference = 0.0;
  for (std::size_t i = 0; i < still.recording.size(); ++i) {
    largest_difference = std::max(largest_difference, std::abs(moved.recording.ppg[i] - still.recording.ppg[i]));
  }
  CHECK(largest_difference > 3.0);
  for (const TimeInterval& burst : moved.motion_bursts) {
    CHECK(burst.end_s > burst.start_s);
    CHECK(burst.end_s - burst.start_s <= 4.5 + 1e-9);
  }
}

TEST_CASE("stress raises the heart rate and lowers RMSSD on average, subject by subject") {
  DatabaseSpec spec;
  spec.subjects = 8;
  spec.recordings_per_state = 2;
  spec.conditions.duration_s = 120.0;
  spec.conditions.sample_rate_hz = 50.0;
  spec.seed = 2024;
  const auto database = generate_labelled_database(spec);
  REQUIRE(database.size() == 32);
  CHECK(database.front().subject_id == "s01");
  CHECK(database.back().subject_id == "s08");
  std::vector<double> hr[2];
  std::vector<double> rmssd[2];
  for (const LabelledRecording& item : database) {
    const auto& recording = item.simulated.recording;
    REQUIRE(recording.has_labels());
    CHECK(recording.label.front() == (item.stressed ? 1 : 0));
    const int state = item.stressed ? 1 : 0;
    hr[state].push_back(true_mean_hr_bpm(item.simulated.beat_times_s, 0.0, 120.0));
    rmssd[state].push_back(rmssd_ms(item.simulated.beat_times_s));
  }
  INFO("HR " << mean(hr[0]) << " -> " << mean(hr[1]) << ", RMSSD " << mean(rmssd[0]) << " -> " << mean(rmssd[1]));
  CHECK(mean(hr[1]) > mean(hr[0]) + 8.0);
  CHECK(mean(rmssd[1]) < 0.8 * mean(rmssd[0]));
  // Subject by subject, too: database order is subject, then unstressed, stressed.
  for (std::size_t s = 0; s < spec.subjects; ++s) {
    const std::size_t rest = 4 * s;
    const std::size_t stress = 4 * s + 2;
    CHECK(database[stress].profile.resting_hr_bpm > database[rest].profile.resting_hr_bpm);
    CHECK(database[stress].profile.breathing_rate_hz > database[rest].profile.breathing_rate_hz);
    CHECK(database[stress].profile.rsa_amplitude_ms < database[rest].profile.rsa_amplitude_ms);
  }
}

TEST_CASE("the simulator refuses impossible settings") {
  PpgSimulator simulator(1);
  RecordingConditions conditions;
  SubjectProfile subject;
  subject.resting_hr_bpm = 10.0;
  CHECK_THROWS_AS(simulator.simulate(subject, conditions), std::invalid_argument);
  conditions.sample_rate_hz = 0.0;
  CHECK_THROWS_AS(simulator.simulate({}, conditions), std::invalid_argument);
  conditions.sample_rate_hz = 100.0;
  conditions.noise_sd = -1.0;
  CHECK_THROWS_AS(simulator.simulate({}, conditions), std::invalid_argument);
}
