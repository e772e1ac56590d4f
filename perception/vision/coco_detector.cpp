#include "perception/vision/coco_detector.h"

#include <opencv2/dnn.hpp>
#include <stdexcept>

#include "perception/tfjs/model_format_error.h"
#include "perception/vision/coco_labels.h"

namespace alplan::perception {

namespace {

constexpr int kInputSize = 512;

}  // namespace

CocoDetector::CocoDetector(const CocoDetectorOptions& options)
    : decoding_(options.decoding),
      model_(load_tfjs_graph_model(options.model_json, {"tower_0/keypoints", "tower_0/wh"})) {}

std::vector<ObjectDetection> CocoDetector::detect(const cv::Mat& bgr_image) {
  if (bgr_image.empty() || bgr_image.type() != CV_8UC3)
    throw std::invalid_argument("CocoDetector::detect: expects an 8-bit BGR image");
  // blobFromImage resizes bilinearly, swaps to RGB and keeps 0-255.
  model_.net.setInput(cv::dnn::blobFromImage(bgr_image, 1.0, cv::Size(kInputSize, kInputSize), cv::Scalar(),
                                             /*swapRB=*/true, /*crop=*/false, CV_32F));
  std::vector<cv::Mat> outputs;
  model_.net.forward(outputs, model_.output_layers);
  const cv::Mat& heatmap = outputs.at(0);
  if (heatmap.dims != 4 || heatmap.size[1] != kCocoClassCount)
    throw ModelFormatError("the CenterNet heatmap does not have the 80 COCO classes");
  const float stride = static_cast<float>(kInputSize) / static_cast<float>(heatmap.size[3]);
  const float scale_x = static_cast<float>(bgr_image.cols) / kInputSize;
  const float scale_y = static_cast<float>(bgr_image.rows) / kInputSize;
  const cv::Rect2f image_area(0, 0, static_cast<float>(bgr_image.cols), static_cast<float>(bgr_image.rows));
  std::vector<ObjectDetection> detections;
  for (const CenterNetBox& found : decode_centernet(heatmap, outputs.at(1), stride, decoding_)) {
    const cv::Rect2f box(found.box.x * scale_x, found.box.y * scale_y, found.box.width * scale_x,
                         found.box.height * scale_y);
    detections.push_back({*coco_label(found.class_id), found.class_id, found.score, box & image_area});
  }
  return detections;
}

}  // namespace alplan::perception
