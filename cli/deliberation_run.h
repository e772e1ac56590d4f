// Layers 2-4 of the paper's deliberation (Fig. 3) once a senior is known to
// be stressed: the face (or a given emotion) through the emotion recogniser,
// the emotion to a goal, the goal into the home's planning problem, then
// plan, act, monitor and repair, with a camera folder as the object
// recogniser. Shared by `alplan deliberate` (stress from one recording) and
// `alplan serve --deliberate` (stress events from the wristbands' service).
#pragma once

#include <string>
#include <vector>

#include "perception/stress_detector.h"

namespace CLI {
class App;
}

namespace alplan::cli {

struct DeliberationSettings {
  std::string dir = ALPLAN_ASSISTED_LIVING_DIR;
  std::string problem = "paper-scenario-1.pddl";
  std::string face;
  std::string emotion;
  int looks = 3;
  std::string camera;
  std::vector<std::string> unavailable;  // OBJECT@TIME
  std::string strategy = "substitute";
};

// --domains-dir, --problem, --face, --emotion, --looks, --camera,
// --unavailable, --strategy.
void add_deliberation_options(CLI::App& command, DeliberationSettings& settings);

// Exit 0 when the senior is comforted or the emotion asks for nothing, 1
// when the run ends with an explained failure; throws CommandInputError on
// bad input.
int deliberate_on_stress(const DeliberationSettings& settings, const std::string& senior,
                         const perception::StressState& stress);

}  // namespace alplan::cli
