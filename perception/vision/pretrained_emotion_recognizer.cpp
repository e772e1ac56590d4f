#include "perception/vision/pretrained_emotion_recognizer.h"

#include <algorithm>
#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "perception/tfjs/model_format_error.h"

namespace alplan::perception {

namespace {

const cv::Size kInputSize{64, 64};

// Human's `annotations` for this model, read through the dataset spellings
// emotion_from_name accepts.
std::array<Emotion, 7> fer2013_classes() {
  const std::array<const char*, 7> annotations = {"angry", "disgust", "fear", "happy", "sad", "surprise", "neutral"};
  std::array<Emotion, 7> classes{};
  std::transform(annotations.begin(), annotations.end(), classes.begin(),
                 [](const char* name) { return *emotion_from_name(name); });
  return classes;
}

}  // namespace

const std::array<Emotion, 7>& PretrainedEmotionRecognizer::output_classes() {
  static const std::array<Emotion, 7> kClasses = fer2013_classes();
  return kClasses;
}

PretrainedEmotionRecognizer::PretrainedEmotionRecognizer(const PretrainedEmotionOptions& options)
    : faces_([&] {
        FaceDetectorOptions faces = options.faces;
        faces.crop_size = kInputSize;
        return faces;
      }()),
      model_(load_tfjs_graph_model(options.model_json, {"Identity"})) {}

std::vector<std::pair<Emotion, float>> PretrainedEmotionRecognizer::classify_face(const cv::Mat& grey_face) {
  if (grey_face.empty() || grey_face.type() != CV_8UC1)
    throw std::invalid_argument("classify_face: expects an 8-bit grey face");
  cv::Mat face = grey_face;
  if (face.size() != kInputSize) cv::resize(grey_face, face, kInputSize, 0, 0, cv::INTER_AREA);
  cv::Mat normalised;
  face.convertTo(normalised, CV_32F, 2.0 / 255.0, -1.0);
  model_.net.setInput(cv::dnn::blobFromImage(normalised));
  const cv::Mat probabilities = model_.net.forward(model_.output_layers.front());
  if (probabilities.total() != output_classes().size())
    throw ModelFormatError("the emotion model gave " + std::to_string(probabilities.total()) + " scores, not 7");
  std::vector<std::pair<Emotion, float>> scores;
  for (std::size_t i = 0; i < output_classes().size(); ++i)
    scores.emplace_back(output_classes()[i], probabilities.ptr<float>()[i]);
  std::stable_sort(scores.begin(), scores.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  return scores;
}

std::vector<FaceEmotion> PretrainedEmotionRecognizer::recognize(const cv::Mat& bgr_image) {
  std::vector<FaceEmotion> emotions;
  for (const DetectedFace& face : faces_.detect(bgr_image)) {
    auto scores = classify_face(face.grey_crop);
    emotions.push_back({face.box, scores.front().first, scores.front().second, std::move(scores)});
  }
  return emotions;
}

}  // namespace alplan::perception
