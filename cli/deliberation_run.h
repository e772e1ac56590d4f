// Layers 2-4 of the paper's deliberation (Fig. 3) once a senior is known to
// be stressed: the face (or a given emotion) through the emotion recogniser,
// the emotion to a goal, the goal into the home's planning problem, then
// plan, act, monitor and repair, with a camera folder as the object
// recogniser. Shared by `alplan deliberate` (stress from one recording) and
// `alplan serve --deliberate` (stress events from the wristbands' service).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "domains/mission_run.h"
#include "perception/goals/goal_generator.h"
#include "perception/stress/stress_detector.h"
#include "perception/vision/object_recognition.h"
#include "perception/vision/pretrained_emotion_recognizer.h"

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

// The home, the emotion network and the object detector are loaded once,
// when the deliberator is made, so that a service deliberating on event
// after event reads no model and no PDDL file again; each run starts from
// the home's problem file.
class Deliberator {
 public:
  // Throws CommandInputError (or the loaders' errors, naming the file) on
  // bad settings: no face or emotion, an unreadable home, a missing camera
  // folder, a malformed --unavailable.
  explicit Deliberator(DeliberationSettings settings);

  // Exit 0 when the senior is comforted or the emotion asks for nothing, 1
  // when the run ends with an explained failure; throws CommandInputError
  // on an unreadable face image.
  int on_stress(const std::string& senior, const perception::StressState& stress);

 private:
  std::optional<perception::EmotionReading> emotion();

  DeliberationSettings settings_;
  domains::LoadedHome home_;
  std::vector<repair::ExogenousEvent> unavailable_;
  std::unique_ptr<perception::PretrainedEmotionRecognizer> faces_;   // with --face
  std::unique_ptr<perception::ImageObjectRecognizer> images_;        // with --camera
};

}  // namespace alplan::cli
