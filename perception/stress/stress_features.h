// From a PPG recording to the windows the stress classifier learns from. The
// features are computed by the wristband's own signal chain
// (firmware/core/wristband_core.h), so the detector trained here sees
// exactly what a wristband sends: one implementation of the filter, the
// peak detector and the windowed averaging everywhere.
//
// Artefact rejection: a window without a heart rate (too few clean beats) or
// flagged for motion is not used (the paper names hand motion as the main
// source of error; averaging over a window is its Discussion's remedy, and
// the core averages over 30 s).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "firmware/core/wristband_core.h"
#include "perception/stress/ppg_recording.h"

namespace alplan::perception {

// The paper's two inputs (heart rate and the interval between peaks), or
// those two with the time-domain HRV measures stress is known to lower.
enum class StressFeatureSet { Paper, PaperWithHrv };

const char* feature_set_name(StressFeatureSet set);
// "paper" or "paper+hrv"; throws std::invalid_argument otherwise.
StressFeatureSet feature_set_from_name(const std::string& name);
std::vector<std::string> feature_names(StressFeatureSet set);

struct StressWindow {
  double end_s = 0.0;  // the window covers (end_s - window, end_s]
  firmware::WindowFeatures features;
  int label = -1;     // the majority label of its samples; -1 unlabelled
  bool usable = false;  // has a heart rate and no motion flag
};

struct WindowingOptions {
  double window_s = 30.0;
  double hop_s = 5.0;
};

// Runs the wristband core over the recording (at the recording's own rate).
// Throws std::invalid_argument when the rate or the windowing is outside
// what the core accepts.
std::vector<StressWindow> stress_windows(const PpgRecording& recording, const WindowingOptions& options = {});

std::vector<float> feature_vector(const firmware::WindowFeatures& features, StressFeatureSet set);

}  // namespace alplan::perception
