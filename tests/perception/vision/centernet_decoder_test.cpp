#include "perception/vision/centernet_decoder.h"

#include <algorithm>
#include <catch2/catch.hpp>

using namespace alplan::perception;

namespace {

// A 1 x C x 8 x 8 heatmap and 1 x 4 x 8 x 8 distances of 2 pixels per side.
struct Outputs {
  explicit Outputs(int classes)
      : heatmap(std::vector<int>{1, classes, 8, 8}, CV_32F, cv::Scalar(0)),
        distances(std::vector<int>{1, 4, 8, 8}, CV_32F, cv::Scalar(2)) {}
  void score(int class_id, int x, int y, float value) { heatmap.ptr<float>(0, class_id)[y * 8 + x] = value; }
  void sides(int x, int y, const std::array<float, 4>& d) {
    for (int i = 0; i < 4; ++i) distances.ptr<float>(0, i)[y * 8 + x] = d[static_cast<std::size_t>(i)];
  }
  cv::Mat heatmap;
  cv::Mat distances;
};

Outputs scene() {
  Outputs outputs(2);
  outputs.score(0, 2, 3, 0.9F);  // a peak, its box from uneven sides
  outputs.sides(2, 3, {1, 2, 3, 4});
  outputs.score(0, 3, 3, 0.5F);  // beside a higher cell: not a peak
  outputs.score(1, 2, 3, 0.7F);  // another class, same box: suppressed
  outputs.score(1, 5, 1, 0.4F);  // a plateau: both cells are peaks
  outputs.score(1, 6, 1, 0.4F);
  outputs.score(1, 6, 6, 0.3F);  // a lone peak
  outputs.score(0, 0, 7, 0.1F);  // under min_score
  return outputs;
}

}  // namespace

TEST_CASE("CenterNet peaks become boxes: local maxima, stride, sides, threshold, class-agnostic NMS") {
  const Outputs outputs = scene();
  const auto boxes = decode_centernet(outputs.heatmap, outputs.distances, 4.0F, CenterNetDecoding{});
  REQUIRE(boxes.size() == 4);
  // Cell (2, 3) at stride 4 is (8, 12); sides 1, 2, 3, 4 give (7, 10)-(11, 16).
  CHECK(boxes[0].class_id == 0);
  CHECK(boxes[0].score == 0.9F);
  CHECK(boxes[0].box == cv::Rect2f(7, 10, 4, 6));
  std::vector<cv::Rect2f> plateau = {boxes[1].box, boxes[2].box};
  std::sort(plateau.begin(), plateau.end(), [](const auto& a, const auto& b) { return a.x < b.x; });
  CHECK(boxes[1].score == 0.4F);
  CHECK(boxes[2].score == 0.4F);
  CHECK(plateau == std::vector<cv::Rect2f>{{18, 2, 4, 4}, {22, 2, 4, 4}});
  CHECK(boxes[3].class_id == 1);
  CHECK(boxes[3].score == 0.3F);
  CHECK(boxes[3].box == cv::Rect2f(22, 22, 4, 4));
}

TEST_CASE("CenterNet decoding honours top-k, the detection cap and the score threshold") {
  const Outputs outputs = scene();
  CenterNetDecoding decoding;
  decoding.max_detections = 2;
  CHECK(decode_centernet(outputs.heatmap, outputs.distances, 4.0F, decoding).size() == 2);
  decoding = CenterNetDecoding{};
  decoding.top_k = 1;
  const auto best = decode_centernet(outputs.heatmap, outputs.distances, 4.0F, decoding);
  REQUIRE(best.size() == 1);
  CHECK(best[0].score == 0.9F);
  decoding = CenterNetDecoding{};
  decoding.min_score = 0.05F;
  decoding.iou_threshold = 1.0F;  // nothing suppressed: the other class's box at (2, 3) returns
  CHECK(decode_centernet(outputs.heatmap, outputs.distances, 4.0F, decoding).size() == 6);
  CHECK_THROWS_AS(decode_centernet(outputs.heatmap, outputs.heatmap, 4.0F, decoding), std::invalid_argument);
}
