#include "tests/firmware/core_runner.h"

#include <algorithm>
#include <cmath>

namespace alplan::test {

CoreRun run_core(const firmware::CoreConfig& config, const std::vector<double>& ppg) {
  firmware::WristbandCore core(config);
  CoreRun run;
  for (double sample : ppg) {
    const firmware::CoreStep step = core.push_sample(static_cast<float>(sample));
    if (step.peak_detected) {
      run.peak_times_s.push_back(step.beat.time_ms / 1000.0);
      run.beats.push_back(step.beat);
    }
    if (step.reading_ready) run.readings.push_back(step.reading);
  }
  return run;
}

double BeatMatch::sensitivity() const {
  const std::size_t truth = true_positives + false_negatives;
  return truth == 0 ? 0.0 : static_cast<double>(true_positives) / static_cast<double>(truth);
}

double BeatMatch::precision() const {
  const std::size_t detected = true_positives + false_positives;
  return detected == 0 ? 0.0 : static_cast<double>(true_positives) / static_cast<double>(detected);
}

namespace {

double nearest_offset(const std::vector<double>& sorted, double t) {
  const auto it = std::lower_bound(sorted.begin(), sorted.end(), t);
  double best = INFINITY;
  if (it != sorted.end()) best = *it - t;
  if (it != sorted.begin() && std::abs(*(it - 1) - t) < std::abs(best)) best = *(it - 1) - t;
  return best;
}

}  // namespace

double detection_lag_s(const std::vector<double>& true_beats_s, const std::vector<double>& detected_s) {
  std::vector<double> lags;
  for (double d : detected_s) {
    const double offset = -nearest_offset(true_beats_s, d);  // detection minus truth
    if (std::abs(offset) < 0.25) lags.push_back(offset);
  }
  if (lags.empty()) return 0.0;
  std::nth_element(lags.begin(), lags.begin() + static_cast<std::ptrdiff_t>(lags.size() / 2), lags.end());
  return lags[lags.size() / 2];
}

BeatMatch match_beats(const std::vector<double>& true_beats_s, const std::vector<double>& detected_s,
                      double tolerance_s, double start_s, double end_s) {
  BeatMatch match;
  match.lag_s = detection_lag_s(true_beats_s, detected_s);
  std::vector<bool> used(true_beats_s.size(), false);
  for (double d : detected_s) {
    const double t = d - match.lag_s;
    if (t < start_s || t > end_s) continue;
    const auto first = std::lower_bound(true_beats_s.begin(), true_beats_s.end(), t - tolerance_s);
    bool matched = false;
    for (auto it = first; it != true_beats_s.end() && *it <= t + tolerance_s; ++it) {
      const auto index = static_cast<std::size_t>(it - true_beats_s.begin());
      if (used[index]) continue;
      used[index] = true;
      matched = true;
      break;
    }
    ++(matched ? match.true_positives : match.false_positives);
  }
  for (std::size_t i = 0; i < true_beats_s.size(); ++i) {
    if (!used[i] && true_beats_s[i] >= start_s && true_beats_s[i] <= end_s) ++match.false_negatives;
  }
  return match;
}

double HeartRateErrors::mean() const {
  if (absolute_bpm.empty()) return 0.0;
  double sum = 0.0;
  for (double e : absolute_bpm) sum += e;
  return sum / static_cast<double>(absolute_bpm.size());
}

double HeartRateErrors::max() const {
  return absolute_bpm.empty() ? 0.0 : *std::max_element(absolute_bpm.begin(), absolute_bpm.end());
}

double HeartRateErrors::percentile(double fraction) const {
  if (absolute_bpm.empty()) return 0.0;
  std::vector<double> sorted = absolute_bpm;
  std::sort(sorted.begin(), sorted.end());
  const auto index = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(sorted.size()))) - 1;
  return sorted[std::min(index, sorted.size() - 1)];
}

HeartRateErrors heart_rate_errors(const CoreRun& run, const std::vector<double>& true_beats_s) {
  HeartRateErrors errors;
  const double lag_s = detection_lag_s(true_beats_s, run.peak_times_s);
  for (const firmware::Reading& reading : run.readings) {
    ++errors.readings;
    if (!reading.features.has_heart_rate) {
      ++errors.without_rate;
      continue;
    }
    const double end_s = static_cast<double>(reading.timestamp_ms) / 1000.0 - lag_s;
    const double truth = perception::true_mean_hr_bpm(true_beats_s, end_s - reading.window_ms / 1000.0, end_s);
    errors.absolute_bpm.push_back(std::abs(static_cast<double>(reading.features.mean_hr_bpm) - truth));
  }
  return errors;
}

TrueVariability true_variability(const std::vector<double>& true_beats_s, double start_s, double end_s) {
  std::vector<double> ibis;
  for (std::size_t i = 1; i < true_beats_s.size(); ++i) {
    if (true_beats_s[i] > start_s && true_beats_s[i] <= end_s) {
      ibis.push_back(1000.0 * (true_beats_s[i] - true_beats_s[i - 1]));
    }
  }
  TrueVariability result;
  if (ibis.size() < 3) return result;
  double mean = 0.0;
  for (double ibi : ibis) mean += ibi;
  mean /= static_cast<double>(ibis.size());
  double squares = 0.0;
  double differences = 0.0;
  for (std::size_t i = 0; i < ibis.size(); ++i) {
    squares += (ibis[i] - mean) * (ibis[i] - mean);
    if (i > 0) differences += (ibis[i] - ibis[i - 1]) * (ibis[i] - ibis[i - 1]);
  }
  result.sdnn_ms = std::sqrt(squares / static_cast<double>(ibis.size() - 1));
  result.rmssd_ms = std::sqrt(differences / static_cast<double>(ibis.size() - 1));
  return result;
}

}  // namespace alplan::test
