// The 80 object classes of COCO detection (Lin et al., "Microsoft COCO:
// Common Objects in Context", ECCV 2014) in the contiguous 0-79 order that
// COCO-trained detectors output, as the Human library lists them
// (src/object/labels.ts, github.com/vladmandic/human).
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace alplan::perception {

inline constexpr int kCocoClassCount = 80;

const std::array<std::string_view, kCocoClassCount>& coco_labels();
// "person" for 0, ..., "toothbrush" for 79; nothing outside 0-79.
std::optional<std::string_view> coco_label(int class_id);
std::optional<int> coco_class_id(std::string_view label);

}  // namespace alplan::perception
