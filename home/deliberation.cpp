#include "home/deliberation.h"

#include <algorithm>

#include "domains/emotion_goals.h"

namespace alplan::home {
namespace {

bool about(const pddl::Atom& a, const std::string& predicate, const std::string& senior) {
  return a.name == predicate && a.args.size() == 1 && a.args[0].name == senior;
}

}  // namespace

std::optional<StressEvent> first_stress_event(StressDetector& detector, const std::string& senior,
                                              const std::vector<StressWindow>& readings) {
  for (const StressWindow& w : readings) {
    const perception::StressObservation seen = detector.observe(senior, w.features);
    if (seen.changed && seen.state.stressed) return StressEvent{senior, w.end_s, seen.state};
  }
  return std::nullopt;
}

std::optional<EmotionReading> read_face(EmotionRecognizer& recognizer, const cv::Mat& image, bool scores_bored) {
  const std::vector<perception::FaceEmotion> faces = recognizer.recognize(image);
  if (faces.empty()) return std::nullopt;
  const auto best = std::max_element(faces.begin(), faces.end(),
                                     [](const perception::FaceEmotion& a, const perception::FaceEmotion& b) { return a.score < b.score; });
  return EmotionReading{best->label, best->score, scores_bored};
}

pddl::Problem reformulate_for_goal(const pddl::Problem& problem, const GeneratedGoal& goal, double now,
                                   const WindowDurations& windows) {
  pddl::Problem out = problem;
  const std::string& senior = goal.senior;
  const auto is_emotion_fact = [&](const pddl::Atom& a) {
    for (const char* e : {"terrified", "sad", "bored"}) {
      if (about(a, e, senior)) return true;
    }
    return false;
  };
  out.init.erase(std::remove_if(out.init.begin(), out.init.end(), is_emotion_fact), out.init.end());
  out.init.push_back(domains::senior_atom(std::string(*perception::emotion_predicate(goal.emotion)), senior));

  const std::string window = goal.emotion == perception::Emotion::Terrified ? "hydration_time" : "comfort_time";
  const bool open = std::any_of(out.init.begin(), out.init.end(), [&](const pddl::Atom& a) { return about(a, window, senior); });
  if (!open) {
    out.init.push_back(domains::senior_atom(window, senior));
    pddl::TimedInitialLiteral close;
    close.time = now + (goal.emotion == perception::Emotion::Terrified ? windows.terrified_s : windows.other_s);
    close.positive = false;
    close.atom = domains::senior_atom(window, senior);
    out.timed_literals.push_back(close);
  }
  out.goal = goal.goal;
  return out;
}

}  // namespace alplan::home
