#include "perception/common/emotion.h"

#include <algorithm>
#include <cctype>
#include <utility>

#include "domains/emotion_goals.h"

namespace alplan::perception {

std::string_view emotion_name(Emotion emotion) {
  switch (emotion) {
    case Emotion::Terrified: return "terrified";
    case Emotion::Angry: return "angry";
    case Emotion::Disgusted: return "disgusted";
    case Emotion::Happy: return "happy";
    case Emotion::Neutral: return "neutral";
    case Emotion::Sad: return "sad";
    case Emotion::Surprised: return "surprised";
    case Emotion::Bored: return "bored";
  }
  return "unknown";
}

std::optional<Emotion> emotion_from_name(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const std::pair<std::string_view, Emotion> spellings[] = {
      {"terrified", Emotion::Terrified}, {"fear", Emotion::Terrified},       {"afraid", Emotion::Terrified},
      {"scared", Emotion::Terrified},    {"angry", Emotion::Angry},          {"anger", Emotion::Angry},
      {"disgusted", Emotion::Disgusted}, {"disgust", Emotion::Disgusted},    {"happy", Emotion::Happy},
      {"happiness", Emotion::Happy},     {"neutral", Emotion::Neutral},      {"sad", Emotion::Sad},
      {"sadness", Emotion::Sad},         {"surprised", Emotion::Surprised},  {"surprise", Emotion::Surprised},
      {"bored", Emotion::Bored},         {"boredom", Emotion::Bored}};
  for (const auto& [spelling, emotion] : spellings) {
    if (lower == spelling) return emotion;
  }
  return std::nullopt;
}

std::optional<std::string_view> goal_predicate(Emotion emotion) {
  return domains::goal_for_emotion(emotion_name(emotion));
}

std::optional<std::string_view> emotion_predicate(Emotion emotion) {
  if (!goal_predicate(emotion)) return std::nullopt;
  return emotion_name(emotion);
}

}  // namespace alplan::perception
