// Objects of the 80 COCO classes (coco_labels.h) with the pretrained
// CenterNet on a MobileNetV3 backbone (github.com/610265158/
// mobilenetv3_centernet) as converted to TensorFlow.js by @vladmandic/human-
// models (MIT; centernet.json), loaded with tfjs_graph_model.h and decoded
// in C++ as centernet_decoder.h describes (the graph's own TopKV2/GatherV2
// tail is cut off: OpenCV has no layers for it).
//
// Preprocessing follows the Human library (github.com/vladmandic/human):
// src/image/image.ts makes the whole image an RGB float tensor of 0-255
// values, no normalisation; src/object/centernet.ts resizes it bilinearly to
// the model's 512x512 input whatever its aspect, and scales boxes back by
// the image's width and height.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "perception/tfjs/tfjs_graph_model.h"
#include "perception/vision/centernet_decoder.h"

namespace alplan::perception {

struct CocoDetectorOptions {
  std::string model_json = std::string(ALPLAN_MODELS_DIR) + "/centernet.json";
  CenterNetDecoding decoding;
};

struct ObjectDetection {
  std::string_view label;  // COCO's name, e.g. "cup"
  int class_id;            // 0-79
  float score;             // the centre's heatmap score in [0, 1]
  cv::Rect2f box;          // in image pixels, clipped to the image
};

class CocoDetector {
 public:
  // Throws ModelFormatError if the model cannot be loaded.
  explicit CocoDetector(const CocoDetectorOptions& options = {});

  // Objects in an 8-bit BGR image, best first.
  std::vector<ObjectDetection> detect(const cv::Mat& bgr_image);

 private:
  CenterNetDecoding decoding_;
  TfjsGraphModel model_;
};

}  // namespace alplan::perception
