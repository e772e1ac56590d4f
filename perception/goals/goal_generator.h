// Goal generation (the paper's layer 2, Section 6.1): once a senior is
// detected as stressed and their emotion recognised, the goal that comforts
// that emotion: terrified -> (soothed s), sad -> (cheerful s), bored ->
// (entertained s). Other emotions, or a senior who is not stressed,
// generate no goal (the paper acts on stress first, then on the emotion).
//
// Boredom. The pretrained FER2013 network has no "bored" class (the paper
// trained one from UMB-DB). Where the recogniser offers no Bored score,
// `EmotionGoalGenerator` decides boredom by a stated rule instead of never:
// a stressed senior whose face shows Neutral as the top emotion in
// `bored_after_neutral` consecutive observations is taken to be bored --
// boredom being the unpleasant, low-arousal state (Russell's circumplex,
// J. Pers. Soc. Psychol. 39:1161, 1980; Eastwood et al., Perspect. Psychol.
// Sci. 7:482, 2012): the body says stress, the face shows no engagement.
// A recogniser that does score Bored (the paper's 8-class CNN trained with
// `alplan perceive emotion train`) is used as it is, and the rule is off.
// Every generated goal says which way its emotion was decided.
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "perception/common/emotion.h"
#include "perception/stress/stress_detector.h"

namespace alplan::perception {

// What the emotion recogniser said about a senior's face.
struct EmotionReading {
  Emotion top = Emotion::Neutral;
  float score = 0.0f;
  bool model_scores_bored = false;  // the recogniser has a Bored class
};

struct GeneratedGoal {
  std::string senior;
  Emotion emotion = Emotion::Neutral;
  pddl::Condition goal;            // (soothed senior1)
  std::vector<std::string> facts;  // what the problem's init must state: (terrified senior1)
  std::string motivation;          // "senior1 is stressed and terrified"
  std::string decided_by;          // "the emotion recogniser (fear 0.91)" or the boredom rule
};

class GoalGenerator {
 public:
  virtual ~GoalGenerator() = default;
  // Called whenever a senior's stress or face is observed, in time order.
  virtual std::optional<GeneratedGoal> generate(const std::string& senior, const StressState& stress,
                                                const EmotionReading& emotion) = 0;
};

struct GoalGenerationOptions {
  std::size_t bored_after_neutral = 3;
  float min_score = 0.3f;  // a weaker top emotion is not acted on
};

class EmotionGoalGenerator : public GoalGenerator {
 public:
  explicit EmotionGoalGenerator(const GoalGenerationOptions& options = {}) : options_(options) {}

  std::optional<GeneratedGoal> generate(const std::string& senior, const StressState& stress,
                                        const EmotionReading& emotion) override;
  // The senior's stress episode is over (calm again, or comforted): the
  // boredom rule's streak starts afresh, so that a senior judged bored once
  // is not bored again on the first neutral look of a later episode.
  void episode_ended(const std::string& senior) { neutral_streak_.erase(senior); }
  // Neutral looks in a row while stressed, in the senior's current episode.
  std::size_t neutral_streak(const std::string& senior) const {
    const auto it = neutral_streak_.find(senior);
    return it == neutral_streak_.end() ? 0 : it->second;
  }
  const GoalGenerationOptions& options() const { return options_; }

 private:
  GoalGenerationOptions options_;
  std::map<std::string, std::size_t> neutral_streak_;
};

}  // namespace alplan::perception
