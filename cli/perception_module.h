// The perception commands (perceive, and the signal service's) live in a
// module that `alplan` loads only when one of them runs: libtorch and
// OpenCV take seconds to start (measured: 2.8 s for a program that only
// links libtorch, 0.5 s for OpenCV's modules), which every `alplan plan`
// and every planner run of the benchmark harness would otherwise pay.
//
// The module exports one C function, kPerceptionEntryPoint, which parses
// and runs the command line as `alplan` received it.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "repair/object_recognizer.h"

namespace alplan::cli {

inline constexpr const char* kPerceptionEntryPoint = "alplan_perception_main";
using PerceptionMain = int (*)(int argc, char** argv);

// The commands the module runs, with a line of help each.
struct ModuleCommand {
  const char* name;
  const char* help;
};
inline constexpr ModuleCommand kPerceptionCommands[] = {
    {"perceive", "Perception: emotions and objects in images, the type ontology, stress detection, training"},
    {"deliberate", "One senior end to end: stress, emotion, goal, plan, act, monitor, repair"},
    {"serve", "The signal service: wristband readings in, stress events out (HTTP/JSON, SQLite)"},
    {"wristband", "Simulated wristbands against the signal service; device tokens"},
    {"home", "The running home: seniors over time, goals, plans, failures, repairs, an event log"},
    {"replay", "Runs a home's log again from its settings and checks it reaches the same events"},
};
inline constexpr const char* kHomeHelp = kPerceptionCommands[4].help;
inline constexpr const char* kReplayHelp = kPerceptionCommands[5].help;

// True for the module's commands, and for `bench service`, `bench soak` and `bench home`
// (the signal service's benchmarks; the others run in alplan itself).
bool runs_in_perception_module(int argc, char** argv);
inline constexpr const char* kBenchServiceHelp =
    "Load benchmark of the signal service: simulated wristbands, readings/s held and latency";
inline constexpr const char* kBenchHomeHelp =
    "The running home at scale: planning latency by reason, goals comforted within their windows";
inline constexpr const char* kBenchSoakHelp =
    "Soak benchmark of the signal service: wristbands for minutes with commit failures, restarts, stalled clients";

// Loads the module (ALPLAN_PERCEPTION_MODULE, else beside the executable)
// and runs the command; prints a clear error and returns 2 if the module
// cannot be loaded.
int run_perception_command(int argc, char** argv);

// The repair study's camera (perception/vision/drawing_camera.h), made in the
// module: the paper's CNN trained once on drawings, and a maker of
// recognizers that picture what the simulator knows and let the network
// name it. The module exports kDrawingCameraEntryPoint as DrawingCameraEntry,
// which fills `make` and `info` (accuracy, training time) or returns false
// with `error` set.
using ObjectCamera = std::function<std::unique_ptr<repair::ObjectRecognizer>(repair::ObjectRecognizer& truth)>;
inline constexpr const char* kDrawingCameraEntryPoint = "alplan_drawing_camera";
using DrawingCameraEntry = bool (*)(const char* types_ttl, ObjectCamera* make, nlohmann::json* info, std::string* error);

// Loads the module and makes the camera; false with `error` set when the
// module cannot be loaded or the camera made.
bool load_drawing_camera(const std::string& types_ttl, ObjectCamera& make, nlohmann::json& info, std::string& error);

}  // namespace alplan::cli
