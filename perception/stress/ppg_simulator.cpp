#include "perception/stress/ppg_simulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace alplan::perception {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kMayerHz = 0.1;
constexpr double kDriftHz = 0.05;
constexpr double kLeadIn_s = 3.0;  // beats start this early so the record opens mid-rhythm

// The pulse wave's shape for a beat after an interval of `ibi_s`: systolic
// width, dicrotic delay and width. The systole shortens less than the
// diastole as the heart speeds up, hence the constant terms.
struct PulseShape {
  double systolic_sd_s;
  double dicrotic_delay_s;
  double dicrotic_sd_s;
};

PulseShape pulse_shape(double ibi_s) {
  const double systolic = 0.05 + 0.05 * ibi_s;
  return {systolic, 0.15 + 0.15 * ibi_s, 1.2 * systolic};
}

double gaussian(double x, double sd) { return std::exp(-0.5 * (x / sd) * (x / sd)); }

void check(const SubjectProfile& subject, const RecordingConditions& conditions) {
  if (!(conditions.sample_rate_hz > 0.0) || !(conditions.duration_s > 0.0)) {
    throw std::invalid_argument("PpgSimulator: the sample rate and the duration must be positive");
  }
  if (!(subject.resting_hr_bpm >= 30.0 && subject.resting_hr_bpm <= 220.0)) {
    throw std::invalid_argument("PpgSimulator: heart rate outside 30-220 bpm");
  }
  if (subject.ibi_jitter_ms < 0.0 || subject.rsa_amplitude_ms < 0.0 || subject.mayer_amplitude_ms < 0.0 ||
      subject.pulse_amplitude < 0.0 || subject.dicrotic_ratio < 0.0 || subject.breathing_rate_hz < 0.0 ||
      conditions.noise_sd < 0.0 || conditions.baseline_wander < 0.0 || conditions.motion.bursts_per_minute < 0.0 ||
      conditions.motion.strength < 0.0 || !(conditions.motion.mean_burst_s > 0.0)) {
    throw std::invalid_argument("PpgSimulator: amplitudes, rates and durations must not be negative");
  }
}

}  // namespace

SubjectProfile under_stress(const SubjectProfile& subject, const StressResponse& response) {
  SubjectProfile stressed = subject;
  stressed.resting_hr_bpm = subject.resting_hr_bpm + response.hr_increase_bpm;
  stressed.ibi_jitter_ms = subject.ibi_jitter_ms * response.hrv_scale;
  stressed.rsa_amplitude_ms = subject.rsa_amplitude_ms * response.hrv_scale;
  stressed.mayer_amplitude_ms = subject.mayer_amplitude_ms * response.hrv_scale;
  stressed.breathing_rate_hz = subject.breathing_rate_hz * response.breathing_rate_scale;
  return stressed;
}

double true_mean_hr_bpm(const std::vector<double>& beat_times_s, double start_s, double end_s) {
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 1; i < beat_times_s.size(); ++i) {
    if (beat_times_s[i] <= start_s || beat_times_s[i] > end_s) continue;
    sum += beat_times_s[i] - beat_times_s[i - 1];
    ++count;
  }
  return count == 0 ? 0.0 : 60.0 * static_cast<double>(count) / sum;
}

PpgSimulator::PpgSimulator(std::uint64_t seed) : engine_(seed) {}

double PpgSimulator::uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

double PpgSimulator::normal(double mean, double sd) {
  // Box-Muller; 1 - u keeps the logarithm's argument in (0, 1].
  const double u = 1.0 - uniform();
  const double v = uniform();
  return mean + sd * std::sqrt(-2.0 * std::log(u)) * std::cos(kTwoPi * v);
}

double PpgSimulator::clamped_normal(double mean, double sd, double low, double high) {
  return std::clamp(normal(mean, sd), low, high);
}

SubjectProfile PpgSimulator::random_subject() {
  SubjectProfile subject;
  subject.resting_hr_bpm = clamped_normal(72.0, 8.0, 55.0, 95.0);
  subject.ibi_jitter_ms = clamped_normal(18.0, 5.0, 6.0, 35.0);
  subject.rsa_amplitude_ms = clamped_normal(35.0, 10.0, 10.0, 65.0);
  subject.mayer_amplitude_ms = clamped_normal(20.0, 6.0, 5.0, 40.0);
  subject.breathing_rate_hz = clamped_normal(0.25, 0.03, 0.17, 0.33);
  subject.pulse_amplitude = clamped_normal(1.0, 0.2, 0.5, 1.5);
  subject.dicrotic_ratio = clamped_normal(0.4, 0.1, 0.15, 0.65);
  return subject;
}

StressResponse PpgSimulator::random_stress_response() {
  StressResponse response;
  response.hr_increase_bpm = clamped_normal(15.0, 5.0, 5.0, 30.0);
  response.hrv_scale = clamped_normal(0.55, 0.1, 0.3, 0.8);
  response.breathing_rate_scale = clamped_normal(1.35, 0.1, 1.1, 1.6);
  return response;
}

std::vector<double> PpgSimulator::beat_times(const SubjectProfile& subject, double duration_s) {
  const double mean_ibi_s = 60.0 / subject.resting_hr_bpm;
  const double breathing_phase = kTwoPi * uniform();
  const double mayer_phase = kTwoPi * uniform();
  std::vector<double> beats;
  double t = -kLeadIn_s + mean_ibi_s * uniform();
  while (t < duration_s + kLeadIn_s) {
    beats.push_back(t);
    const double rsa = subject.rsa_amplitude_ms * std::sin(kTwoPi * subject.breathing_rate_hz * t + breathing_phase);
    const double mayer = subject.mayer_amplitude_ms * std::sin(kTwoPi * kMayerHz * t + mayer_phase);
    const double ibi_ms = 1000.0 * mean_ibi_s + rsa + mayer + normal(0.0, subject.ibi_jitter_ms);
    t += std::max(ibi_ms, 250.0) / 1000.0;
  }
  return beats;
}

SimulatedRecording PpgSimulator::simulate(const SubjectProfile& subject, const RecordingConditions& conditions) {
  check(subject, conditions);
  const std::vector<double> beats = beat_times(subject, conditions.duration_s);
  const auto samples = static_cast<std::size_t>(std::floor(conditions.duration_s * conditions.sample_rate_hz));
  const double amplitude = subject.pulse_amplitude;

  // Per beat: its height (breathing modulates it by 10 %, plus 3 % noise)
  // and shape.
  const double breathing_phase = kTwoPi * uniform();
  std::vector<double> heights(beats.size());
  std::vector<PulseShape> shapes(beats.size());
  for (std::size_t k = 0; k < beats.size(); ++k) {
    // The shape follows the interval before the beat, the filling time that
    // sets the stroke (the Frank-Starling mechanism).
    const double ibi = k > 0 ? beats[k] - beats[k - 1] : 60.0 / subject.resting_hr_bpm;
    heights[k] = amplitude * (1.0 + 0.1 * std::sin(kTwoPi * subject.breathing_rate_hz * beats[k] + breathing_phase)) *
                 (1.0 + normal(0.0, 0.03));
    shapes[k] = pulse_shape(ibi);
  }

  SimulatedRecording result;
  PpgRecording& recording = result.recording;
  recording.time_s.resize(samples);
  recording.ppg.resize(samples);
  const double drift_phase = kTwoPi * uniform();
  std::size_t first_beat = 0;
  for (std::size_t i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / conditions.sample_rate_hz;
    while (first_beat < beats.size() && beats[first_beat] < t - 2.0) ++first_beat;
    double pulse = 0.0;
    for (std::size_t k = first_beat; k < beats.size() && beats[k] < t + 1.0; ++k) {
      const double dt = t - beats[k];
      pulse += heights[k] * (gaussian(dt, shapes[k].systolic_sd_s) +
                             subject.dicrotic_ratio * gaussian(dt - shapes[k].dicrotic_delay_s, shapes[k].dicrotic_sd_s));
    }
    const double wander =
        conditions.baseline_wander * amplitude *
        (std::sin(kTwoPi * subject.breathing_rate_hz * t + breathing_phase + std::numbers::pi / 3.0) +
         0.5 * std::sin(kTwoPi * kDriftHz * t + drift_phase));
    recording.time_s[i] = t;
    recording.ppg[i] = conditions.dc_level + pulse + wander + normal(0.0, conditions.noise_sd * amplitude);
  }
  result.motion_bursts = add_motion(recording.ppg, conditions, amplitude);
  for (double beat : beats) {
    if (beat >= 0.0 && beat <= conditions.duration_s) result.beat_times_s.push_back(beat);
  }
  return result;
}

std::vector<TimeInterval> PpgSimulator::add_motion(std::vector<double>& ppg, const RecordingConditions& conditions,
                                                   double pulse_amplitude) {
  std::vector<TimeInterval> bursts;
  const MotionArtefacts& motion = conditions.motion;
  if (motion.bursts_per_minute <= 0.0 || motion.strength <= 0.0) return bursts;
  const double fs = conditions.sample_rate_hz;
  const double peak = motion.strength * pulse_amplitude;
  double t = 0.0;
  while (true) {
    t += -std::log(1.0 - uniform()) * 60.0 / motion.bursts_per_minute;
    if (t >= conditions.duration_s) break;
    const double length = motion.mean_burst_s * (0.5 + uniform());
    const TimeInterval burst{t, std::min(t + length, conditions.duration_s)};
    bursts.push_back(burst);

    double frequency[3];
    double phase[3];
    for (int j = 0; j < 3; ++j) {
      frequency[j] = 0.3 + 2.7 * uniform();
      phase[j] = kTwoPi * uniform();
    }
    // Spikes: about two a second, each a signed jump decaying in 30-80 ms.
    std::vector<std::pair<double, double>> spikes;  // time, height
    std::vector<double> decay;
    for (double s = burst.start_s; s < burst.end_s; s += -std::log(1.0 - uniform()) / 2.0) {
      spikes.emplace_back(s, (uniform() < 0.5 ? -1.0 : 1.0) * peak * (0.5 + uniform()));
      decay.push_back(0.03 + 0.05 * uniform());
    }
    const auto first = static_cast<std::size_t>(std::ceil(burst.start_s * fs));
    for (std::size_t i = first; i < ppg.size() && static_cast<double>(i) / fs < burst.end_s + 0.5; ++i) {
      const double u = static_cast<double>(i) / fs;
      double disturbance = 0.0;
      if (u < burst.end_s) {
        const double taper = std::sin(std::numbers::pi * (u - burst.start_s) / (burst.end_s - burst.start_s));
        for (int j = 0; j < 3; ++j) disturbance += peak / 3.0 * taper * std::sin(kTwoPi * frequency[j] * u + phase[j]);
      }
      for (std::size_t k = 0; k < spikes.size(); ++k) {
        if (u >= spikes[k].first) disturbance += spikes[k].second * std::exp(-(u - spikes[k].first) / decay[k]);
      }
      ppg[i] += disturbance;
    }
    t = burst.end_s;
  }
  return bursts;
}

std::vector<LabelledRecording> generate_labelled_database(const DatabaseSpec& spec) {
  PpgSimulator simulator(spec.seed);
  std::vector<LabelledRecording> database;
  database.reserve(spec.subjects * spec.recordings_per_state * 2);
  for (std::size_t s = 0; s < spec.subjects; ++s) {
    const SubjectProfile rest = simulator.random_subject();
    const SubjectProfile stress = under_stress(rest, simulator.random_stress_response());
    const std::string id = (s + 1 < 10 ? "s0" : "s") + std::to_string(s + 1);
    for (const bool stressed : {false, true}) {
      for (std::size_t r = 0; r < spec.recordings_per_state; ++r) {
        LabelledRecording item;
        item.subject_id = id;
        item.stressed = stressed;
        item.profile = stressed ? stress : rest;
        item.simulated = simulator.simulate(item.profile, spec.conditions);
        item.simulated.recording.label.assign(item.simulated.recording.size(), stressed ? 1 : 0);
        database.push_back(std::move(item));
      }
    }
  }
  return database;
}

}  // namespace alplan::perception
