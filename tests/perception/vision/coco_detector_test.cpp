#include "perception/vision/coco_detector.h"

#include <catch2/catch.hpp>
#include <opencv2/imgcodecs.hpp>

#include "perception/vision/coco_labels.h"

using namespace alplan::perception;

namespace {

const std::string kSkimageData = "/usr/lib/python3/dist-packages/skimage/data/";

float iou(const cv::Rect2f& a, const cv::Rect2f& b) {
  const float common = (a & b).area();
  return common / (a.area() + b.area() - common);
}

}  // namespace

TEST_CASE("the coffee photo shows a cup where the cup is") {
  CocoDetector detector;
  const cv::Mat image = cv::imread(kSkimageData + "coffee.png");
  REQUIRE_FALSE(image.empty());
  const auto detections = detector.detect(image);
  REQUIRE_FALSE(detections.empty());
  const ObjectDetection& best = detections.front();
  CHECK(best.label == "cup");
  CHECK(best.class_id == *coco_class_id("cup"));
  CHECK(best.score >= 0.3F);
  CHECK(best.score <= 1.0F);
  // The cup (rim to foot, handle included) measured by hand in the 600x400
  // photo; PASCAL VOC counts IoU >= 0.5 as a correct detection.
  const cv::Rect2f cup(cv::Point2f(172, 18), cv::Point2f(410, 290));
  CHECK(iou(best.box, cup) >= 0.5F);
  for (const ObjectDetection& detection : detections) {
    CHECK(detection.score >= 0.2F);
    CHECK((detection.box & cv::Rect2f(0, 0, 600, 400)) == detection.box);
  }
}

TEST_CASE("other photos show their main object first") {
  CocoDetector detector;
  const std::pair<const char*, std::string_view> photos[] = {
      {"astronaut.png", "person"}, {"motorcycle_left.png", "motorcycle"}, {"horse.png", "horse"}};
  for (const auto& [name, label] : photos) {
    const cv::Mat image = cv::imread(kSkimageData + name);
    REQUIRE_FALSE(image.empty());
    INFO(name);
    const auto detections = detector.detect(image);
    REQUIRE_FALSE(detections.empty());
    CHECK(detections.front().label == label);
  }
}

TEST_CASE("COCO labels are the 80 classes in detector order") {
  CHECK(coco_labels().size() == 80);
  CHECK(coco_label(0) == "person");
  CHECK(coco_label(41) == "cup");
  CHECK(coco_label(79) == "toothbrush");
  CHECK_FALSE(coco_label(80).has_value());
  CHECK(coco_class_id("dining table") == 60);
  CHECK_FALSE(coco_class_id("sofa").has_value());
}
