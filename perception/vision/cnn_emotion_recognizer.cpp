#include "perception/vision/cnn_emotion_recognizer.h"

#include <algorithm>
#include <stdexcept>

namespace alplan::perception {

CnnEmotionRecognizer::CnnEmotionRecognizer(std::shared_ptr<const CnnClassifier> model, const FaceDetectorOptions& faces)
    : model_(std::move(model)), faces_(faces) {
  for (const std::string& name : model_->classes()) {
    const std::optional<Emotion> e = emotion_from_name(name);
    if (!e) throw std::invalid_argument("the model's class '" + name + "' is not an emotion the paper knows");
    classes_.push_back(*e);
  }
}

bool CnnEmotionRecognizer::scores_bored() const {
  return std::find(classes_.begin(), classes_.end(), Emotion::Bored) != classes_.end();
}

std::vector<FaceEmotion> CnnEmotionRecognizer::recognize(const cv::Mat& bgr_image) {
  std::vector<FaceEmotion> out;
  for (const DetectedFace& face : faces_.detect(bgr_image)) {
    const std::vector<float> scores = model_->scores(face.grey_crop);
    FaceEmotion f;
    f.face = face.box;
    for (std::size_t i = 0; i < scores.size(); ++i) f.scores.emplace_back(classes_[i], scores[i]);
    std::stable_sort(f.scores.begin(), f.scores.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    f.label = f.scores.front().first;
    f.score = f.scores.front().second;
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace alplan::perception
