// What the deliberation loop needs from facial emotion recognition (the
// paper's layer 1): the emotion on every face of a camera image, with the
// recogniser's confidence, so that a terrified, sad or bored senior raises
// the goal emotion.h names. Implementations: PretrainedEmotionRecognizer
// (mini-Xception on FER2013).
#pragma once

#include <opencv2/core.hpp>
#include <utility>
#include <vector>

#include "perception/common/emotion.h"

namespace alplan::perception {

struct FaceEmotion {
  cv::Rect face;  // in image pixels
  Emotion label;  // the highest-scoring emotion
  float score;    // its score in [0, 1]
  // Every emotion the recogniser knows with its score, highest first;
  // emotions it was not trained on are absent, not zero.
  std::vector<std::pair<Emotion, float>> scores;
};

class EmotionRecognizer {
 public:
  virtual ~EmotionRecognizer() = default;
  // One entry per face in an 8-bit BGR image, largest face first; none if
  // no face is seen.
  virtual std::vector<FaceEmotion> recognize(const cv::Mat& bgr_image) = 0;
};

}  // namespace alplan::perception
