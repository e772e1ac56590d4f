#include "home/given_face.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <opencv2/imgcodecs.hpp>

#include "home/deliberation.h"
#include "perception/vision/pretrained_emotion_recognizer.h"

namespace alplan::home {

GivenFace::GivenFace(std::string face, std::string emotion) : face_(std::move(face)), emotion_(std::move(emotion)) {
  if (emotion_.empty() && face_.empty()) {
    throw std::invalid_argument("give the seniors' face (--face IMAGE) or the emotion (--emotion NAME)");
  }
  if (!emotion_.empty() && !perception::emotion_from_name(emotion_)) {
    throw std::invalid_argument("--emotion " + emotion_ + ": not an emotion (terrified, sad, bored, happy, ...)");
  }
  if (emotion_.empty()) faces_ = std::make_unique<perception::PretrainedEmotionRecognizer>();
}

GivenFace::~GivenFace() = default;
GivenFace::GivenFace(GivenFace&&) noexcept = default;

std::optional<perception::EmotionReading> GivenFace::look(std::string& note) {
  if (!emotion_.empty()) {
    const perception::Emotion e = *perception::emotion_from_name(emotion_);
    note = "[emotion] given on the command line: " + std::string(perception::emotion_name(e));
    return perception::EmotionReading{e, 1.0f, true};
  }
  if (!std::filesystem::is_regular_file(face_)) throw std::invalid_argument(face_ + ": no such file");
  const cv::Mat image = cv::imread(face_, cv::IMREAD_COLOR);
  if (image.empty()) throw std::invalid_argument(face_ + ": cannot read an image from this file");
  const auto reading = read_face(*faces_, image, false);
  if (!reading) {
    note = "[emotion] no face in " + face_;
    return reading;
  }
  char score[32];
  std::snprintf(score, sizeof score, "%.3f", static_cast<double>(reading->score));
  note = "[emotion] face in " + face_ + ": " + std::string(perception::emotion_name(reading->top)) + " " + score;
  return reading;
}

}  // namespace alplan::home
