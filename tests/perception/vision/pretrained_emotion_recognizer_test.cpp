#include "perception/vision/pretrained_emotion_recognizer.h"

#include <catch2/catch.hpp>
#include <numeric>
#include <opencv2/imgcodecs.hpp>

using namespace alplan::perception;

namespace {

const std::string kSkimageData = "/usr/lib/python3/dist-packages/skimage/data/";

}  // namespace

TEST_CASE("the smiling astronaut is one face, recognised as happy") {
  PretrainedEmotionRecognizer recognizer;
  const cv::Mat image = cv::imread(kSkimageData + "astronaut.png");
  REQUIRE_FALSE(image.empty());
  const std::vector<FaceEmotion> emotions = recognizer.recognize(image);
  REQUIRE(emotions.size() == 1);
  const FaceEmotion& face = emotions[0];
  CHECK(face.label == Emotion::Happy);
  CHECK(face.score > 0.9F);
  REQUIRE(face.scores.size() == 7);
  CHECK(face.scores.front() == std::make_pair(face.label, face.score));
  for (std::size_t i = 1; i < face.scores.size(); ++i) CHECK(face.scores[i - 1].second >= face.scores[i].second);
  const float total = std::accumulate(face.scores.begin(), face.scores.end(), 0.0F,
                                      [](float sum, const auto& entry) { return sum + entry.second; });
  CHECK(total == Approx(1.0F).margin(1e-4));
  CHECK(face.face.contains(cv::Point(223, 147)));  // her mouth
}

TEST_CASE("the model's classes are FER2013's in Human's order, fear read as terrified, no bored") {
  const auto& classes = PretrainedEmotionRecognizer::output_classes();
  CHECK(classes == std::array<Emotion, 7>{Emotion::Angry, Emotion::Disgusted, Emotion::Terrified, Emotion::Happy,
                                          Emotion::Sad, Emotion::Surprised, Emotion::Neutral});
}

TEST_CASE("an image without a face yields no emotion") {
  PretrainedEmotionRecognizer recognizer;
  const cv::Mat image = cv::imread(kSkimageData + "coffee.png");
  REQUIRE_FALSE(image.empty());
  CHECK(recognizer.recognize(image).empty());
}
