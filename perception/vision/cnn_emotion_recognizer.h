// Facial emotion with the paper's own CNN (cnn_classifier.h) as trained by
// `alplan perceive emotion train` on KDEF (and UMB-DB's bored faces where the
// data exists): the Haar cascade finds the faces, the CNN labels the grey
// crops. Class names are read with emotion_from_name; a model trained with
// a "bored" class scores Bored, so goal generation believes it instead of
// applying its boredom rule.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "perception/vision/cnn_classifier.h"
#include "perception/vision/emotion_recognizer.h"
#include "perception/vision/face_detector.h"

namespace alplan::perception {

class CnnEmotionRecognizer : public EmotionRecognizer {
 public:
  // Throws std::invalid_argument if a class of the model is not an emotion.
  CnnEmotionRecognizer(std::shared_ptr<const CnnClassifier> model, const FaceDetectorOptions& faces = {});

  std::vector<FaceEmotion> recognize(const cv::Mat& bgr_image) override;
  bool scores_bored() const;

 private:
  std::shared_ptr<const CnnClassifier> model_;
  std::vector<Emotion> classes_;
  FaceDetector faces_;
};

}  // namespace alplan::perception
