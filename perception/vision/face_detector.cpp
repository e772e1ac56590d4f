#include "perception/vision/face_detector.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "perception/tfjs/model_format_error.h"

namespace alplan::perception {

namespace {

cv::Mat to_grey(const cv::Mat& image) {
  if (image.empty() || image.depth() != CV_8U) throw std::invalid_argument("FaceDetector: expects an 8-bit image");
  if (image.channels() == 1) return image;
  cv::Mat grey;
  cv::cvtColor(image, grey, image.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
  return grey;
}

cv::Rect grown(const cv::Rect& box, double margin, const cv::Size& bounds) {
  const int dx = static_cast<int>(box.width * margin);
  const int dy = static_cast<int>(box.height * margin);
  const cv::Rect larger(box.x - dx, box.y - dy, box.width + 2 * dx, box.height + 2 * dy);
  return larger & cv::Rect(cv::Point(0, 0), bounds);
}

}  // namespace

FaceDetector::FaceDetector(const FaceDetectorOptions& options) : options_(options) {
  if (!cascade_.load(options_.cascade_path))
    throw ModelFormatError(options_.cascade_path + ": cannot read a cascade classifier from it");
}

std::vector<DetectedFace> FaceDetector::detect(const cv::Mat& image) {
  const cv::Mat grey = to_grey(image);
  // Equalising only for the cascade: the crop keeps the image's own tones,
  // as the expression model saw in training.
  cv::Mat equalised;
  cv::equalizeHist(grey, equalised);
  std::vector<cv::Rect> boxes;
  cascade_.detectMultiScale(equalised, boxes, options_.scale_factor, options_.min_neighbors, 0, options_.min_face_size);
  std::sort(boxes.begin(), boxes.end(), [](const cv::Rect& a, const cv::Rect& b) { return a.area() > b.area(); });
  std::vector<DetectedFace> faces;
  for (const cv::Rect& box : boxes) {
    DetectedFace face{box, cv::Mat()};
    cv::resize(grey(grown(box, options_.crop_margin, grey.size())), face.grey_crop, options_.crop_size, 0, 0,
               cv::INTER_AREA);
    faces.push_back(std::move(face));
  }
  return faces;
}

}  // namespace alplan::perception
