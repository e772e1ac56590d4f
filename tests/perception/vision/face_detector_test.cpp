#include "perception/vision/face_detector.h"

#include <catch2/catch.hpp>
#include <cstring>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "perception/tfjs/model_format_error.h"

using namespace alplan::perception;

namespace {

const std::string kSkimageData = "/usr/lib/python3/dist-packages/skimage/data/";

// skimage's lfw_subset.npy (Debian python3-skimage): 200 grey 25x25 crops
// from Labeled Faces in the Wild, float64 in [0, 1]; the first 100 are
// faces, the others background patches of the same photos.
std::vector<cv::Mat> lfw_subset() {
  std::ifstream in(kSkimageData + "lfw_subset.npy", std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() > 10);
  REQUIRE(bytes.substr(1, 5) == "NUMPY");
  REQUIRE(bytes.find("'descr': '<f8'") != std::string::npos);
  REQUIRE(bytes.find("'shape': (200, 25, 25)") != std::string::npos);
  const std::size_t header = 10 + static_cast<unsigned char>(bytes[8]) + 256U * static_cast<unsigned char>(bytes[9]);
  REQUIRE(bytes.size() == header + 200 * 25 * 25 * sizeof(double));
  std::vector<cv::Mat> images;
  for (std::size_t i = 0; i < 200; ++i) {
    cv::Mat pixels(25, 25, CV_64F);
    std::memcpy(pixels.data, bytes.data() + header + i * 625 * sizeof(double), 625 * sizeof(double));
    cv::Mat grey;
    pixels.convertTo(grey, CV_8U, 255.0);
    images.push_back(grey);
  }
  return images;
}

}  // namespace

TEST_CASE("the astronaut photo has exactly one face, around her eyes and mouth") {
  FaceDetector detector;
  const cv::Mat image = cv::imread(kSkimageData + "astronaut.png");
  REQUIRE_FALSE(image.empty());
  const auto faces = detector.detect(image);
  REQUIRE(faces.size() == 1);
  // Eyes and mouth located by hand in the 512x512 photo.
  for (const cv::Point feature : {cv::Point(202, 112), cv::Point(246, 112), cv::Point(223, 147)})
    CHECK(faces[0].box.contains(feature));
  CHECK(faces[0].box.width < 150);
  CHECK(faces[0].grey_crop.type() == CV_8UC1);
  CHECK(faces[0].grey_crop.size() == cv::Size(64, 64));
}

TEST_CASE("photos without a frontal face yield none") {
  FaceDetector detector;
  // A coffee cup, a cat, a rocket, and the cameraman seen in profile.
  for (const char* name : {"coffee.png", "chelsea.png", "rocket.jpg", "camera.png"}) {
    const cv::Mat image = cv::imread(kSkimageData + name);
    REQUIRE_FALSE(image.empty());
    INFO(name);
    CHECK(detector.detect(image).empty());
  }
}

TEST_CASE("the detector finds the faces of an LFW sample and not its background patches") {
  FaceDetectorOptions options;
  options.min_face_size = {24, 24};
  FaceDetector detector(options);
  const auto images = lfw_subset();
  int faces_found = 0;
  int backgrounds_taken_for_faces = 0;
  for (std::size_t i = 0; i < images.size(); ++i) {
    // The crops are tight and tiny: enlarge them and give the cascade the
    // margin its 24x24 window expects.
    cv::Mat enlarged;
    cv::resize(images[i], enlarged, {100, 100}, 0, 0, cv::INTER_CUBIC);
    cv::copyMakeBorder(enlarged, enlarged, 20, 20, 20, 20, cv::BORDER_REPLICATE);
    const bool found = !detector.detect(enlarged).empty();
    (i < 100 ? faces_found : backgrounds_taken_for_faces) += found ? 1 : 0;
  }
  CHECK(faces_found >= 90);
  CHECK(backgrounds_taken_for_faces <= 5);
}

TEST_CASE("a missing cascade file is a ModelFormatError naming it") {
  FaceDetectorOptions options;
  options.cascade_path = "/nonexistent/cascade.xml";
  CHECK_THROWS_AS(FaceDetector(options), ModelFormatError);
  CHECK_THROWS_WITH(FaceDetector(options), Catch::Contains("/nonexistent/cascade.xml"));
}
