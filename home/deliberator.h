// Layers 2-4 of the paper's deliberation (Fig. 3) for one senior known to
// be stressed: the face (or a given emotion) through the emotion
// recogniser, the emotion to a goal, the goal into the home's planning
// problem, then plan, act, monitor and repair, with a camera folder as the
// object recogniser. What `alplan deliberate` (stress from one recording)
// and `alplan serve --deliberate` (stress events from the wristbands'
// service) run; the home with many seniors is home_run.h.
#pragma once

#include <functional>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "domains/mission_run.h"
#include "home/given_face.h"
#include "perception/vision/camera_object_recognizer.h"
#include "perception/goals/goal_generator.h"
#include "perception/vision/pretrained_emotion_recognizer.h"
#include "perception/stress/stress_detector.h"
#include "repair/world_simulator.h"

namespace alplan::home {

struct DeliberatorSettings {
  std::string dir;                     // domain.pddl, types.ttl and the problems
  std::string problem = "paper-scenario-1.pddl";
  std::string face;                    // an image of the senior's face, read at every look
  std::string emotion;                 // or the emotion, said to be given
  // Looks at the face per stress event, `look_interval_s` apart in real
  // time (the face read anew each time: a camera may have refreshed the
  // image). One image read thrice at one instant is one look, not three.
  int looks = 1;
  double look_interval_s = 20.0;
  // How the deliberator waits between looks; null: it sleeps. Tests record.
  std::function<void(double seconds)> wait;
  std::string camera;                  // a folder of views per location
  std::vector<repair::ExogenousEvent> events;  // scripted: objects becoming unavailable
  std::string strategy = "substitute";
};

// What one stress event led to.
struct Deliberation {
  std::vector<std::string> notes;  // what perception said, in order, for people
  std::optional<perception::EmotionReading> emotion;  // the last look's; none: no face seen
  std::optional<perception::GeneratedGoal> goal;
  std::optional<domains::MissionRun> run;
  std::string no_plan;  // the home offers no plan for the goal: why
  bool comforted() const { return run && run->report.goal_reached; }
};

class Deliberator {
 public:
  // Loads the home, the emotion network and the object detector once, so
  // that a service deliberating on event after event reads no model and no
  // PDDL file again. Throws std::invalid_argument on bad settings (no face
  // or emotion, an unknown emotion, a missing camera folder), or the
  // loaders' errors naming the file.
  explicit Deliberator(DeliberatorSettings settings);
  ~Deliberator();

  // Every look reads the face image anew (what the camera shows now), and
  // one goal generator serves every event, so the boredom rule counts looks
  // taken at different times. Throws std::invalid_argument on an
  // unreadable face image.
  Deliberation on_stress(const std::string& senior, const perception::StressState& stress);
  // The senior is calm again: the stress episode is over, and the boredom
  // rule's count of neutral looks starts afresh with the next.
  void on_calm(const std::string& senior) { generator_.episode_ended(senior); }

 private:
  std::optional<perception::EmotionReading> look(std::vector<std::string>& notes);
  void wait(double seconds) const;
  domains::MissionInput mission_input(const std::string& senior, const perception::GeneratedGoal& goal);

  DeliberatorSettings settings_;
  domains::LoadedHome home_;
  perception::EmotionGoalGenerator generator_;
  GivenFace face_;
  std::unique_ptr<perception::ImageObjectRecognizer> images_;       // with a camera
  // The mission's camera; a new one per run: its names belong to one mission.
  std::unique_ptr<perception::FolderCamera> camera_;
  std::unique_ptr<perception::CameraObjectRecognizer> eyes_;
};

}  // namespace alplan::home
