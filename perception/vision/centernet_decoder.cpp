#include "perception/vision/centernet_decoder.h"

#include <algorithm>
#include <opencv2/dnn.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace alplan::perception {

namespace {

struct Peak {
  int class_id;
  int x;
  int y;
  float score;
};

void check_shapes(const cv::Mat& heatmap, const cv::Mat& distances) {
  const bool heatmap_ok = heatmap.dims == 4 && heatmap.type() == CV_32F && heatmap.size[0] == 1;
  const bool distances_ok = distances.dims == 4 && distances.type() == CV_32F && distances.size[0] == 1 &&
                            distances.size[1] == 4 && heatmap_ok && distances.size[2] == heatmap.size[2] &&
                            distances.size[3] == heatmap.size[3];
  if (!heatmap_ok || !distances_ok)
    throw std::invalid_argument("decode_centernet: expects a 1xCxHxW heatmap and 1x4xHxW distances, CV_32F");
}

// Steps 1, 2 and the score threshold of 4: a peak under min_score would be
// dropped after top-k anyway, and dropping it first changes no ranks above.
std::vector<Peak> best_peaks(const cv::Mat& heatmap, const CenterNetDecoding& decoding) {
  const int classes = heatmap.size[1];
  const int rows = heatmap.size[2];
  const int cols = heatmap.size[3];
  std::vector<Peak> peaks;
  cv::Mat neighbourhood_max;
  for (int class_id = 0; class_id < classes; ++class_id) {
    const cv::Mat plane(rows, cols, CV_32F, const_cast<float*>(heatmap.ptr<float>(0, class_id)));
    // dilate's default border is neutral for max, as SAME max-pooling's.
    cv::dilate(plane, neighbourhood_max, cv::Mat::ones(3, 3, CV_8U));
    for (int y = 0; y < rows; ++y) {
      const float* scores = plane.ptr<float>(y);
      const float* maxima = neighbourhood_max.ptr<float>(y);
      for (int x = 0; x < cols; ++x) {
        if (scores[x] == maxima[x] && scores[x] >= decoding.min_score) peaks.push_back({class_id, x, y, scores[x]});
      }
    }
  }
  std::stable_sort(peaks.begin(), peaks.end(), [](const Peak& a, const Peak& b) { return a.score > b.score; });
  if (peaks.size() > static_cast<std::size_t>(std::max(decoding.top_k, 0))) peaks.resize(decoding.top_k);
  return peaks;
}

}  // namespace

std::vector<CenterNetBox> decode_centernet(const cv::Mat& heatmap, const cv::Mat& distances, float stride,
                                           const CenterNetDecoding& decoding) {
  check_shapes(heatmap, distances);
  const int cols = heatmap.size[3];
  std::vector<CenterNetBox> candidates;
  std::vector<cv::Rect2d> rects;
  std::vector<float> scores;
  for (const Peak& peak : best_peaks(heatmap, decoding)) {
    const int cell = peak.y * cols + peak.x;
    float side[4];
    for (int i = 0; i < 4; ++i) side[i] = distances.ptr<float>(0, i)[cell];
    const float cx = stride * static_cast<float>(peak.x);
    const float cy = stride * static_cast<float>(peak.y);
    const cv::Rect2f box(cv::Point2f(cx - side[0], cy - side[1]), cv::Point2f(cx + side[2], cy + side[3]));
    candidates.push_back({peak.class_id, peak.score, box});
    rects.emplace_back(box.x, box.y, box.width, box.height);
    scores.push_back(peak.score);
  }
  std::vector<int> kept;
  cv::dnn::NMSBoxes(rects, scores, decoding.min_score, decoding.iou_threshold, kept);
  std::vector<CenterNetBox> boxes;
  for (int index : kept) {
    if (static_cast<int>(boxes.size()) >= decoding.max_detections) break;
    boxes.push_back(candidates[static_cast<std::size_t>(index)]);
  }
  return boxes;
}

}  // namespace alplan::perception
