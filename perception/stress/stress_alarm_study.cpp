#include "perception/stress/stress_alarm_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>

#include "perception/stress/stress_features.h"

namespace alplan::perception {
namespace {

struct Senior {
  std::uint64_t seed = 0;
  bool stressed = false;
  std::vector<StressWindow> windows;
};

// The stress events ("became stressed") of one senior's readings, as the
// end times of the windows that raised them.
std::vector<double> stress_events(const StressClassifier& model, const AlarmStudyOptions& options,
                                  const AlarmStudyDetector& d, const Senior& senior) {
  ClassifierStressDetector detector(model, options.smoothing, d.calibration);
  std::vector<double> events;
  for (const StressWindow& w : senior.windows) {
    const StressObservation seen = detector.observe("senior", w.features);
    if (seen.changed && seen.state.stressed) events.push_back(w.end_s);
  }
  return events;
}

void count(AlarmStudyRow& row, const Senior& senior, const std::vector<double>& events, const AlarmStudyOptions& o) {
  const double onset_s = o.onset_minutes * 60.0;
  if (!senior.stressed) {
    row.calm_seniors += 1;
    row.calm_events += events.size();
    row.calm_hours += o.minutes / 60.0;
    if (!events.empty()) {
      row.calm_alarmed += 1;
      row.alarmed_seeds.push_back(senior.seed);
    }
    return;
  }
  row.stressed_seniors += 1;
  // An event from a window ending by the onset saw calm time only: a false
  // alarm. One from a window straddling the onset counts as detection.
  if (std::any_of(events.begin(), events.end(), [&](double t) { return t <= onset_s; })) row.early_alarmed += 1;
  const auto first = std::find_if(events.begin(), events.end(), [&](double t) { return t > onset_s; });
  if (first == events.end()) return;
  row.detected += 1;
  row.latencies_s.push_back(*first - onset_s);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

PpgRecording simulated_senior(std::uint64_t seed, double calm_s, double stressed_s,
                              const RecordingConditions& conditions, double drift_bpm) {
  PpgSimulator simulator(seed);
  const SubjectProfile calm = simulator.random_subject();
  const StressResponse response = simulator.random_stress_response();
  // Without drift one piece per state; with it, minute-long pieces whose
  // resting rate follows a slow swing (a 20-minute period, its phase from
  // the seed: deterministic without another random stream).
  const double piece_s = drift_bpm > 0.0 ? 60.0 : std::max(calm_s, stressed_s);
  const double phase = 6.283185307179586 * std::fmod(static_cast<double>(seed) * 0.6180339887498949, 1.0);
  PpgRecording out;
  for (double t = 0.0; t < calm_s + stressed_s - 1e-9;) {
    const bool stressed = t >= calm_s;
    const double length = std::min(piece_s, (stressed ? calm_s + stressed_s : calm_s) - t);
    SubjectProfile profile = calm;
    profile.resting_hr_bpm += drift_bpm * std::sin(6.283185307179586 * (t + 0.5 * length) / 1200.0 + phase);
    if (stressed) profile = under_stress(profile, response);
    RecordingConditions c = conditions;
    c.duration_s = length;
    const PpgRecording piece = simulator.simulate(profile, c).recording;
    const double offset = out.time_s.empty() ? 0.0 : out.time_s.back() + 1.0 / c.sample_rate_hz;
    for (std::size_t i = 0; i < piece.size(); ++i) {
      out.time_s.push_back(offset + piece.time_s[i]);
      out.ppg.push_back(piece.ppg[i]);
    }
    t += length;
  }
  return out;
}

std::string AlarmStudyDetector::name() const {
  std::string out = feature_set_name(features);
  if (calibration.readings == 0) return out + ", one model for all";
  out += ", own baseline (first " + std::to_string(calibration.readings) + " readings";
  if (calibration.follow_readings == 0) return out + ", fixed)";
  return out + ", then following them while calm, over " + std::to_string(calibration.follow_readings) + ")";
  return out;
}

AlarmStudyReport run_alarm_study(const AlarmStudyOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (!(options.onset_minutes > 0.0 && options.onset_minutes < options.minutes)) {
    throw std::invalid_argument("the stress onset must lie inside the recording");
  }
  std::vector<Senior> seniors;
  for (std::size_t n = 0; n < options.seniors; ++n) {
    const std::uint64_t seed = options.first_seed + n;
    const double total_s = options.minutes * 60.0, onset_s = options.onset_minutes * 60.0;
    seniors.push_back({seed, false, stress_windows(simulated_senior(seed, total_s, 0.0, options.conditions, options.drift_bpm))});
    seniors.push_back(
        {seed, true, stress_windows(simulated_senior(seed, onset_s, total_s - onset_s, options.conditions, options.drift_bpm))});
  }
  std::map<StressFeatureSet, StressClassifier> models;
  AlarmStudyReport report;
  report.options = options;
  for (const AlarmStudyDetector& d : options.detectors) {
    if (models.count(d.features) == 0) {
      SimulatedModelSpec spec = options.training;
      spec.classifier.features = d.features;
      models.emplace(d.features, train_simulated_stress_classifier(spec));
    }
    AlarmStudyRow row;
    row.detector = d;
    for (const Senior& s : seniors) count(row, s, stress_events(models.at(d.features), options, d, s), options);
    report.rows.push_back(row);
  }
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

std::string AlarmStudyReport::markdown() const {
  std::string out =
      "| detector | calm seniors alarmed | false events per hour | stressed seniors detected | median latency | "
      "slowest | stressed seniors alarmed before the onset |\n|---|---|---|---|---|---|---|\n";
  char line[512];
  for (const AlarmStudyRow& r : rows) {
    const double slowest = r.latencies_s.empty() ? 0.0 : *std::max_element(r.latencies_s.begin(), r.latencies_s.end());
    char latency[64] = "-";
    if (!r.latencies_s.empty()) std::snprintf(latency, sizeof latency, "%.0f s | %.0f s", median(r.latencies_s), slowest);
    else std::snprintf(latency, sizeof latency, "- | -");
    std::snprintf(line, sizeof line, "| %s | %zu / %zu | %.2f | %zu / %zu | %s | %zu / %zu |\n",
                  r.detector.name().c_str(), r.calm_alarmed, r.calm_seniors, r.events_per_hour(), r.detected,
                  r.stressed_seniors, latency, r.early_alarmed, r.stressed_seniors);
    out += line;
  }
  return out;
}

nlohmann::json AlarmStudyReport::json() const {
  nlohmann::json rows_json = nlohmann::json::array();
  for (const AlarmStudyRow& r : rows) {
    rows_json.push_back({{"detector", r.detector.name()},
                         {"features", feature_set_name(r.detector.features)},
                         {"calibration_readings", r.detector.calibration.readings},
                         {"follow_readings", r.detector.calibration.follow_readings},
                         {"calm_seniors", r.calm_seniors},
                         {"calm_alarmed", r.calm_alarmed},
                         {"calm_alarmed_seeds", r.alarmed_seeds},
                         {"false_alarm_rate", r.calm_seniors ? static_cast<double>(r.calm_alarmed) / r.calm_seniors : 0.0},
                         {"calm_events", r.calm_events},
                         {"false_events_per_hour", r.events_per_hour()},
                         {"stressed_seniors", r.stressed_seniors},
                         {"detected", r.detected},
                         {"stressed_alarmed_before_onset", r.early_alarmed},
                         {"latencies_s", r.latencies_s},
                         {"median_latency_s", median(r.latencies_s)}});
  }
  return {{"seniors", options.seniors},
          {"first_seed", options.first_seed},
          {"minutes", options.minutes},
          {"onset_minutes", options.onset_minutes},
          {"sample_rate_hz", options.conditions.sample_rate_hz},
          {"motion_bursts_per_minute", options.conditions.motion.bursts_per_minute},
          {"drift_bpm", options.drift_bpm},
          {"training_seed", options.training.seed},
          {"model_kind", model_kind_name(options.training.classifier.kind)},
          {"rows", rows_json},
          {"seconds", seconds}};
}

}  // namespace alplan::perception
