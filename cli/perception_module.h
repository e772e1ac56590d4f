// The perception commands (perceive, and the signal service's) live in a
// module that `alplan` loads only when one of them runs: libtorch and
// OpenCV take seconds to start (measured: 2.8 s for a program that only
// links libtorch, 0.5 s for OpenCV's modules), which every `alplan plan`
// and every planner run of the benchmark harness would otherwise pay.
//
// The module exports one C function, kPerceptionEntryPoint, which parses
// and runs the command line as `alplan` received it.
#pragma once

#include <string>
#include <vector>

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
};

// True for the module's commands, and for `bench service` and `bench soak`
// (the signal service's benchmarks; the others run in alplan itself).
bool runs_in_perception_module(int argc, char** argv);
inline constexpr const char* kBenchServiceHelp =
    "Load benchmark of the signal service: simulated wristbands, readings/s held and latency";
inline constexpr const char* kBenchSoakHelp =
    "Soak benchmark of the signal service: wristbands for minutes with commit failures, restarts, stalled clients";

// Loads the module (ALPLAN_PERCEPTION_MODULE, else beside the executable)
// and runs the command; prints a clear error and returns 2 if the module
// cannot be loaded.
int run_perception_command(int argc, char** argv);

}  // namespace alplan::cli
