// The emotions the deliberation reacts to, and the goals they generate (the
// paper's Section 6.1): terrified -> (soothed s), sad -> (cheerful s),
// bored -> (entertained s); any other emotion generates no goal.
//
// The classes are the paper's: KDEF's seven (afraid, angry, disgusted, happy,
// neutral, sad, surprised; "afraid" is the paper's "terrified") plus "bored",
// which the paper took from UMB-DB. Models trained elsewhere name them
// differently (FER2013 says "fear", "disgust"); `emotion_from_name` accepts
// those spellings.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace alplan::perception {

enum class Emotion { Terrified, Angry, Disgusted, Happy, Neutral, Sad, Surprised, Bored };

inline constexpr std::array<Emotion, 8> kAllEmotions = {Emotion::Terrified, Emotion::Angry,   Emotion::Disgusted,
                                                        Emotion::Happy,     Emotion::Neutral, Emotion::Sad,
                                                        Emotion::Surprised, Emotion::Bored};

// "terrified", "angry", ... as the paper and the domain spell them.
std::string_view emotion_name(Emotion emotion);
// Accepts the paper's names and the common dataset spellings (fear, afraid,
// disgust, happiness, sadness, surprise, boredom), case-insensitively.
std::optional<Emotion> emotion_from_name(std::string_view name);

// The predicate of the goal an emotion calls for, e.g. "soothed" for
// Terrified; nothing for emotions the robot does not act on.
std::optional<std::string_view> goal_predicate(Emotion emotion);
// The domain's predicate stating the emotion, e.g. "terrified" (only the
// three the domain models).
std::optional<std::string_view> emotion_predicate(Emotion emotion);

}  // namespace alplan::perception
