// Facial emotion with the pretrained mini-Xception of Arriaga, Valdenegro-
// Toro and Plöger ("Real-time Convolutional Neural Networks for Emotion and
// Gender Classification", 2017; github.com/oarriaga/face_classification),
// trained on FER2013, as converted to TensorFlow.js by @vladmandic/human-
// models (MIT; emotion.json). Faces come from the Haar cascade
// (face_detector.h).
//
// The model reads a 64x64x1 grey face and outputs 7 softmax scores. Label
// order and preprocessing follow the Human library's src/gear/emotion.ts
// (github.com/vladmandic/human): annotations = ['angry', 'disgust', 'fear',
// 'happy', 'sad', 'surprise', 'neutral']; grey = 0.2989 R + 0.5870 G +
// 0.1140 B of the face in [0, 1], then (grey - 0.5) * 2, i.e. [-1, 1] (the
// original's preprocess_input(x, v2=True)). FER2013's "fear" is the paper's
// Terrified; the model knows no Bored.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "perception/tfjs/tfjs_graph_model.h"
#include "perception/vision/emotion_recognizer.h"
#include "perception/vision/face_detector.h"

namespace alplan::perception {

struct PretrainedEmotionOptions {
  std::string model_json = std::string(ALPLAN_MODELS_DIR) + "/emotion.json";
  FaceDetectorOptions faces;
};

class PretrainedEmotionRecognizer : public EmotionRecognizer {
 public:
  // Throws ModelFormatError if the model or the cascade cannot be loaded.
  explicit PretrainedEmotionRecognizer(const PretrainedEmotionOptions& options = {});

  std::vector<FaceEmotion> recognize(const cv::Mat& bgr_image) override;

  // The scores of one 8-bit grey face crop (resized to 64x64 if it is not),
  // highest first.
  std::vector<std::pair<Emotion, float>> classify_face(const cv::Mat& grey_face);

  // The model's output classes, in output order.
  static const std::array<Emotion, 7>& output_classes();

 private:
  FaceDetector faces_;
  TfjsGraphModel model_;
};

}  // namespace alplan::perception
