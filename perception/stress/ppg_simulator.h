// Synthetic wrist PPG with known beats, for testing the wristband's signal
// chain and for training the stressed/unstressed classifier before real
// recordings exist. Seeded and deterministic: the same seed gives the same
// recording (the random numbers come from std::mt19937_64 through our own
// uniform and normal transforms, since the standard distributions differ
// between standard libraries).
//
// The model, per beat k at time t_k (the systolic peak):
//  - timing: IBI_k = mean IBI + RSA * sin(2 pi f_breath t_k + phase)
//                   + Mayer * sin(2 pi 0.1 Hz t_k + phase) + N(0, jitter^2),
//    i.e. respiratory sinus arrhythmia at the breathing rate, the ~0.1 Hz
//    baroreflex (Mayer) wave and beat-to-beat noise (Task Force of the ESC
//    and NASPE, Circulation 93(5):1043-1065, 1996, for the bands);
//  - shape: two Gaussians, the systolic wave at t_k and the dicrotic wave
//    after it, both scaled with the beat's interval, the amplitude modulated
//    by breathing (Tang, Chen, Ward & Elgendi, "Synthetic photoplethysmogram
//    generation using two Gaussian functions", Sci. Rep. 10:13883, 2020);
//  - baseline wander at the breathing rate plus a slow 0.05 Hz drift;
//    white sensor noise;
//  - motion artefacts, optional: bursts arriving as a Poisson process, each
//    a tapered sum of three large sinusoids of 0.3-3 Hz (inside the pulse
//    band, which is what makes motion hard) plus impulsive spikes with a
//    30-80 ms exponential decay.
// Amplitudes are relative to the pulse amplitude (1 by default); the
// polarity is "blood volume up", with systolic peaks pointing up.
//
// Stress. Acute psychological stress withdraws vagal tone: heart rate rises,
// high-frequency HRV (and with it RMSSD) falls (Kim et al., "Stress and
// Heart Rate Variability: A Meta-Analysis and Review of the Literature",
// Psychiatry Investig. 15(3):235-245, 2018), and breathing quickens
// (Grassmann et al., "Respiratory Changes in Response to Cognitive Load: A
// Systematic Review", Neural Plast. 2016:8146809). The shifts chosen here, in
// the range such laboratory stressors as the Trier Social Stress Test produce
// (Kirschbaum, Pirke & Hellhammer, Neuropsychobiology 28:76-81, 1993):
// heart rate +15 bpm, all three IBI variability terms x0.55, breathing rate
// x1.35 (15 -> about 20 breaths/min); in the labelled database each subject
// draws its own response around these (+15 +- 5 bpm, x0.55 +- 0.1,
// x1.35 +- 0.1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "perception/stress/ppg_recording.h"

namespace alplan::perception {

struct SubjectProfile {
  double resting_hr_bpm = 70.0;
  double ibi_jitter_ms = 20.0;      // SD of the white beat-to-beat term
  double rsa_amplitude_ms = 35.0;   // respiratory sinus arrhythmia
  double mayer_amplitude_ms = 20.0; // 0.1 Hz baroreflex wave
  double breathing_rate_hz = 0.25;  // 15 breaths/min
  double pulse_amplitude = 1.0;
  double dicrotic_ratio = 0.4;      // dicrotic / systolic wave amplitude
};

struct StressResponse {
  double hr_increase_bpm = 15.0;
  double hrv_scale = 0.55;
  double breathing_rate_scale = 1.35;
};

// The subject under stress: HR up, the IBI variability terms scaled down,
// breathing faster.
SubjectProfile under_stress(const SubjectProfile& subject, const StressResponse& response);

struct MotionArtefacts {
  double bursts_per_minute = 0.0;  // 0: none
  double strength = 3.0;           // peak disturbance / pulse amplitude
  double mean_burst_s = 3.0;       // bursts last 0.5-1.5 times this
};

struct RecordingConditions {
  double sample_rate_hz = 100.0;
  double duration_s = 60.0;
  double noise_sd = 0.03;          // / pulse amplitude
  double baseline_wander = 0.5;    // / pulse amplitude
  double dc_level = 0.0;           // added to every sample
  MotionArtefacts motion{};
};

struct TimeInterval {
  double start_s = 0.0;
  double end_s = 0.0;
};

struct SimulatedRecording {
  PpgRecording recording;              // unlabelled
  std::vector<double> beat_times_s;    // the systolic peaks within the recording
  std::vector<TimeInterval> motion_bursts;
};

// The mean heart rate of the true beats whose interval ends in
// (start_s, end_s]: 60 / mean IBI; 0 without such intervals.
double true_mean_hr_bpm(const std::vector<double>& beat_times_s, double start_s, double end_s);

class PpgSimulator {
 public:
  explicit PpgSimulator(std::uint64_t seed);

  // Throws std::invalid_argument for a non-positive rate or duration, a
  // heart rate outside 30-220 bpm, or negative amplitudes.
  SimulatedRecording simulate(const SubjectProfile& subject, const RecordingConditions& conditions);

  // A random subject: resting HR 72 +- 8 bpm (55-95), jitter 18 +- 5 ms,
  // RSA 35 +- 10 ms, Mayer 20 +- 6 ms, breathing 0.25 +- 0.03 Hz.
  SubjectProfile random_subject();
  StressResponse random_stress_response();

 private:
  double uniform();  // [0, 1)
  double normal(double mean, double sd);
  double clamped_normal(double mean, double sd, double low, double high);
  std::vector<double> beat_times(const SubjectProfile& subject, double duration_s);
  std::vector<TimeInterval> add_motion(std::vector<double>& ppg, const RecordingConditions& conditions,
                                       double pulse_amplitude);

  std::mt19937_64 engine_;
};

struct DatabaseSpec {
  std::size_t subjects = 10;
  std::size_t recordings_per_state = 2;  // each subject: this many unstressed and stressed
  RecordingConditions conditions{};      // the same for every recording
  std::uint64_t seed = 1;
};

struct LabelledRecording {
  std::string subject_id;  // "s01", "s02", ...
  bool stressed = false;
  SubjectProfile profile;  // as simulated (stress already applied)
  SimulatedRecording simulated;  // its recording carries the label column (1 stressed, 0 not)
};

// subjects x (recordings_per_state unstressed + recordings_per_state
// stressed), subject by subject; deterministic in the spec.
std::vector<LabelledRecording> generate_labelled_database(const DatabaseSpec& spec);

}  // namespace alplan::perception
