// The online deliberation of the paper's Fig. 3 for one senior, over the
// interfaces only (perception senses, this decides what to do with it): the wristband's readings go to a StressDetector (layer
// 1); on a stress event the senior's face goes to an EmotionRecognizer and
// the emotion to a GoalGenerator (layer 2); the goal reformulates the
// planning problem (layer 3), which the caller plans and executes with the
// monitor (layer 4, repair/), whose ObjectRecognizer can be the camera's.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "perception/goals/goal_generator.h"
#include "perception/stress/stress_detector.h"
#include "perception/stress/stress_features.h"
#include "perception/vision/emotion_recognizer.h"

namespace alplan::home {

using perception::EmotionReading;
using perception::EmotionRecognizer;
using perception::GeneratedGoal;
using perception::StressDetector;
using perception::StressState;
using perception::StressWindow;

struct StressEvent {
  std::string senior;
  double time_s = 0.0;  // the end of the window that tipped the decision
  StressState state;
};

// Layer 1: the first time the senior becomes stressed in these readings.
std::optional<StressEvent> first_stress_event(StressDetector& detector, const std::string& senior,
                                              const std::vector<StressWindow>& readings);

// Layer 2, the face: the most confident face's emotion, or nothing when the
// image shows no face.
std::optional<EmotionReading> read_face(EmotionRecognizer& recognizer, const cv::Mat& image, bool scores_bored);

struct WindowDurations {
  double terrified_s = 600.0;  // the paper's Discussion: terror is the most urgent
  double other_s = 1200.0;
};

// Layer 3: the problem with the generated goal as its goal, the senior's
// emotion facts replaced by the generated one, and the senior's comfort
// window (hydration_time for terrified, comfort_time otherwise) opened from
// `now` if the problem has none, closed by a timed initial literal.
pddl::Problem reformulate_for_goal(const pddl::Problem& problem, const GeneratedGoal& goal, double now,
                                   const WindowDurations& windows = {});

}  // namespace alplan::home
