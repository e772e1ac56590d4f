// Frontal faces in an image with OpenCV's boosted cascade of Haar-like
// features (Viola & Jones, "Rapid Object Detection using a Boosted Cascade
// of Simple Features", CVPR 2001; the cascade is Lienhart's
// haarcascade_frontalface_default.xml, shipped by Debian's opencv-data).
// Each face comes with the grey crop a facial-expression model reads.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/objdetect.hpp>
#include <string>
#include <vector>

namespace alplan::perception {

struct FaceDetectorOptions {
  std::string cascade_path = std::string(ALPLAN_CASCADES_DIR) + "/haarcascade_frontalface_default.xml";
  // Pyramid step and the neighbouring detections a face needs: OpenCV's
  // usual values, which keep false positives on textured backgrounds rare.
  double scale_factor = 1.1;
  int min_neighbors = 5;
  // Smaller faces carry too few pixels for an expression.
  cv::Size min_face_size{48, 48};
  // The grey crop: the face box grown by `crop_margin` of its size on each
  // side (clipped to the image), resized to `crop_size`.
  double crop_margin = 0.0;
  cv::Size crop_size{64, 64};
};

struct DetectedFace {
  cv::Rect box;       // in image pixels
  cv::Mat grey_crop;  // CV_8UC1, crop_size
};

class FaceDetector {
 public:
  // Throws ModelFormatError naming the cascade file if it cannot be read.
  explicit FaceDetector(const FaceDetectorOptions& options = {});

  // Faces in an 8-bit BGR (or grey) image, largest first. Grey is the
  // ITU-R BT.601 luma (0.299 R + 0.587 G + 0.114 B), the weights the emotion
  // models' trainers and Human use.
  std::vector<DetectedFace> detect(const cv::Mat& image);

 private:
  FaceDetectorOptions options_;
  cv::CascadeClassifier cascade_;
};

}  // namespace alplan::perception
