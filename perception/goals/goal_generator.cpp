#include "perception/goals/goal_generator.h"

#include <cstdio>

#include "domains/emotion_goals.h"

namespace alplan::perception {

std::optional<GeneratedGoal> EmotionGoalGenerator::generate(const std::string& senior, const StressState& stress,
                                                            const EmotionReading& emotion) {
  std::size_t& streak = neutral_streak_[senior];
  streak = (stress.stressed && emotion.top == Emotion::Neutral) ? streak + 1 : 0;
  if (!stress.stressed || emotion.score < options_.min_score) return std::nullopt;

  Emotion decided = emotion.top;
  char evidence[96];
  std::snprintf(evidence, sizeof evidence, "the emotion recogniser (%s %.2f)",
                std::string(emotion_name(emotion.top)).c_str(), static_cast<double>(emotion.score));
  std::string decided_by = evidence;
  if (!emotion.model_scores_bored && emotion.top == Emotion::Neutral && streak >= options_.bored_after_neutral) {
    decided = Emotion::Bored;
    decided_by = "the boredom rule: stressed with a neutral face in " + std::to_string(streak) +
                 " observations in a row (the recogniser has no bored class)";
  }
  const std::optional<std::string_view> predicate = goal_predicate(decided);
  if (!predicate) return std::nullopt;

  GeneratedGoal g;
  g.senior = senior;
  g.emotion = decided;
  g.goal = domains::senior_condition(std::string(*predicate), senior);
  g.facts = {"(" + std::string(*emotion_predicate(decided)) + " " + senior + ")"};
  g.motivation = senior + " is stressed and " + std::string(emotion_name(decided));
  g.decided_by = decided_by;
  return g;
}

}  // namespace alplan::perception
