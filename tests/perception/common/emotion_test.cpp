#include <catch2/catch.hpp>

#include "perception/common/emotion.h"

using alplan::perception::Emotion;
using namespace alplan::perception;

TEST_CASE("each of the paper's three emotions calls for its goal, the others for none") {
  CHECK(goal_predicate(Emotion::Terrified) == "soothed");
  CHECK(goal_predicate(Emotion::Sad) == "cheerful");
  CHECK(goal_predicate(Emotion::Bored) == "entertained");
  for (Emotion e : {Emotion::Angry, Emotion::Disgusted, Emotion::Happy, Emotion::Neutral, Emotion::Surprised}) {
    CHECK_FALSE(goal_predicate(e).has_value());
    CHECK_FALSE(emotion_predicate(e).has_value());
  }
  CHECK(emotion_predicate(Emotion::Terrified) == "terrified");
}

TEST_CASE("dataset spellings of emotions are read as the paper's classes") {
  CHECK(emotion_from_name("fear") == Emotion::Terrified);
  CHECK(emotion_from_name("AFRAID") == Emotion::Terrified);
  CHECK(emotion_from_name("disgust") == Emotion::Disgusted);
  CHECK(emotion_from_name("Surprise") == Emotion::Surprised);
  CHECK(emotion_from_name("boredom") == Emotion::Bored);
  CHECK_FALSE(emotion_from_name("contempt").has_value());
  for (Emotion e : kAllEmotions) CHECK(emotion_from_name(emotion_name(e)) == e);
}
