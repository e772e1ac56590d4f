#include "perception/stress/stress_features.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <map>
#include <stdexcept>

namespace alplan::perception {

const char* feature_set_name(StressFeatureSet set) {
  return set == StressFeatureSet::Paper ? "paper" : "paper+hrv";
}

StressFeatureSet feature_set_from_name(const std::string& name) {
  if (name == "paper") return StressFeatureSet::Paper;
  if (name == "paper+hrv") return StressFeatureSet::PaperWithHrv;
  throw std::invalid_argument("unknown stress feature set '" + name + "': expected paper or paper+hrv");
}

std::vector<std::string> feature_names(StressFeatureSet set) {
  if (set == StressFeatureSet::Paper) return {"hr_bpm", "ibi_ms"};
  return {"hr_bpm", "ibi_ms", "sdnn_ms", "rmssd_ms"};
}

std::vector<float> feature_vector(const firmware::WindowFeatures& f, StressFeatureSet set) {
  if (set == StressFeatureSet::Paper) return {f.mean_hr_bpm, f.mean_ibi_ms};
  return {f.mean_hr_bpm, f.mean_ibi_ms, f.sdnn_ms, f.rmssd_ms};
}

std::vector<StressWindow> stress_windows(const PpgRecording& recording, const WindowingOptions& options) {
  if (recording.size() < 2) return {};
  firmware::CoreConfig config;
  config.sample_rate_hz = static_cast<float>(recording.sample_rate_hz());
  config.window_ms = static_cast<std::uint32_t>(std::lround(options.window_s * 1000.0));
  config.hop_ms = static_cast<std::uint32_t>(std::lround(options.hop_s * 1000.0));
  config.start_time_ms = static_cast<std::uint64_t>(std::llround(recording.time_s.front() * 1000.0));
  if (const firmware::ConfigError error = firmware::check_config(config); error != firmware::ConfigError::None) {
    throw std::invalid_argument(std::string("the wristband core cannot process this recording: ") +
                                firmware::config_error_name(error) + " (rate " +
                                std::to_string(config.sample_rate_hz) + " Hz, window " +
                                std::to_string(options.window_s) + " s, hop " + std::to_string(options.hop_s) + " s)");
  }
  // The core lives on the heap here: it is sized for a microcontroller's
  // static storage, not for a host thread's stack.
  auto core = std::make_unique<firmware::WristbandCore>(config);
  std::vector<StressWindow> windows;
  for (std::size_t i = 0; i < recording.size(); ++i) {
    const firmware::CoreStep step = core->push_sample(static_cast<float>(recording.ppg[i]));
    if (!step.reading_ready) continue;
    StressWindow w;
    w.end_s = static_cast<double>(step.reading.timestamp_ms) / 1000.0;
    w.features = step.reading.features;
    w.usable = w.features.has_heart_rate && !w.features.motion_artefact;
    if (recording.has_labels()) {
      std::map<int, std::size_t> votes;
      const double start = w.end_s - static_cast<double>(step.reading.window_ms) / 1000.0;
      const auto first = std::upper_bound(recording.time_s.begin(), recording.time_s.end(), start);
      const auto last = std::upper_bound(first, recording.time_s.end(), w.end_s);
      for (auto t = first; t != last; ++t) votes[recording.label[static_cast<std::size_t>(t - recording.time_s.begin())]] += 1;
      std::size_t best = 0;
      for (const auto& [label, count] : votes) {
        if (count > best) best = count, w.label = label;
      }
    }
    windows.push_back(w);
  }
  return windows;
}

}  // namespace alplan::perception
