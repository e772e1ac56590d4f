#include <catch2/catch.hpp>

#include "perception/goals/goal_generator.h"

using namespace alplan::perception;

namespace {
StressState stressed() {
  StressState s;
  s.stressed = true;
  s.stressed_fraction = 0.8;
  s.votes = 6;
  return s;
}
}  // namespace

TEST_CASE("a stressed senior's emotion generates the paper's goal") {
  EmotionGoalGenerator generator;
  const auto terrified = generator.generate("senior1", stressed(), {Emotion::Terrified, 0.9f, false});
  REQUIRE(terrified);
  CHECK(terrified->goal.atom.name == "soothed");
  CHECK(terrified->goal.atom.args.at(0).name == "senior1");
  CHECK(terrified->facts == std::vector<std::string>{"(terrified senior1)"});
  CHECK(terrified->motivation == "senior1 is stressed and terrified");
  CHECK_THAT(terrified->decided_by, Catch::Contains("fear") || Catch::Contains("terrified"));
  CHECK(generator.generate("senior2", stressed(), {Emotion::Sad, 0.7f, false})->goal.atom.name == "cheerful");
  CHECK(generator.generate("senior3", stressed(), {Emotion::Bored, 0.7f, true})->goal.atom.name == "entertained");
}

TEST_CASE("no goal without stress, for other emotions, or for a weak reading") {
  EmotionGoalGenerator generator;
  CHECK_FALSE(generator.generate("senior1", StressState{}, {Emotion::Terrified, 0.9f, false}));
  for (Emotion e : {Emotion::Angry, Emotion::Disgusted, Emotion::Happy, Emotion::Surprised}) {
    CHECK_FALSE(generator.generate("senior1", stressed(), {e, 0.9f, false}));
  }
  CHECK_FALSE(generator.generate("senior1", stressed(), {Emotion::Sad, 0.1f, false}));
}

TEST_CASE("boredom: decided by the stated rule when the recogniser has no bored class") {
  EmotionGoalGenerator generator({3, 0.3f});
  CHECK_FALSE(generator.generate("senior1", stressed(), {Emotion::Neutral, 0.8f, false}));
  CHECK_FALSE(generator.generate("senior1", stressed(), {Emotion::Neutral, 0.8f, false}));
  const auto third = generator.generate("senior1", stressed(), {Emotion::Neutral, 0.8f, false});
  REQUIRE(third);
  CHECK(third->emotion == Emotion::Bored);
  CHECK(third->goal.atom.name == "entertained");
  CHECK_THAT(third->decided_by, Catch::Contains("boredom rule"));
  // A calm moment breaks the streak.
  generator.generate("senior2", stressed(), {Emotion::Neutral, 0.8f, false});
  generator.generate("senior2", StressState{}, {Emotion::Neutral, 0.8f, false});
  generator.generate("senior2", stressed(), {Emotion::Neutral, 0.8f, false});
  CHECK_FALSE(generator.generate("senior2", stressed(), {Emotion::Neutral, 0.8f, false}));
  // A model with a bored class is believed: neutral stays neutral.
  for (int i = 0; i < 5; ++i) CHECK_FALSE(generator.generate("senior3", stressed(), {Emotion::Neutral, 0.8f, true}));
}

TEST_CASE("boredom: the streak starts afresh with each stress episode") {
  EmotionGoalGenerator generator;
  for (int i = 0; i < 2; ++i) CHECK_FALSE(generator.generate("senior1", stressed(), {Emotion::Neutral, 0.8f, false}));
  REQUIRE(generator.generate("senior1", stressed(), {Emotion::Neutral, 0.8f, false}));
  // Without an end of episode, the next neutral look is a fourth in a row.
  CHECK(generator.generate("senior1", stressed(), {Emotion::Neutral, 0.8f, false}));
  generator.episode_ended("senior1");
  CHECK_FALSE(generator.generate("senior1", stressed(), {Emotion::Neutral, 0.8f, false}));
  CHECK_FALSE(generator.generate("senior1", stressed(), {Emotion::Neutral, 0.8f, false}));
  CHECK(generator.generate("senior1", stressed(), {Emotion::Neutral, 0.8f, false}));
}
