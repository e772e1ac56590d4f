// The deliberation's options and printing, shared by `alplan deliberate`
// (stress from one recording) and `alplan serve --deliberate` (stress
// events from the wristbands' service); the deliberation itself is
// home/deliberator.h.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "home/deliberator.h"
#include "perception/stress/stress_detector.h"

namespace CLI {
class App;
}

namespace alplan::cli {

struct DeliberationSettings {
  std::string dir = ALPLAN_ASSISTED_LIVING_DIR;
  std::string problem = "paper-scenario-1.pddl";
  std::string face;
  std::string emotion;
  int looks = 1;
  double look_interval = 20.0;
  std::string camera;
  std::vector<std::string> unavailable;  // OBJECT@TIME
  std::string strategy = "substitute";
};

// --domains-dir, --problem, --face, --emotion, --looks, --camera,
// --unavailable, --strategy.
void add_deliberation_options(CLI::App& command, DeliberationSettings& settings);

// The CLI's face of home::Deliberator: prints what each stress event led
// to as `alplan deliberate` always has.
class Deliberator {
 public:
  // Throws CommandInputError (or the loaders' errors, naming the file) on
  // bad settings: no face or emotion, an unreadable home, a missing camera
  // folder, a malformed --unavailable.
  explicit Deliberator(const DeliberationSettings& settings);

  // Exit 0 when the senior is comforted or the emotion asks for nothing, 1
  // when the run ends with an explained failure; throws CommandInputError
  // on an unreadable face image.
  int on_stress(const std::string& senior, const perception::StressState& stress);
  // The senior is calm again: their stress episode ends.
  void on_calm(const std::string& senior) { deliberator_.on_calm(senior); }

 private:
  home::Deliberator deliberator_;
};

}  // namespace alplan::cli
