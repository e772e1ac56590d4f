#include "perception/vision/object_recognition.h"

#include <algorithm>
#include <set>

namespace alplan::perception {

ImageObjectRecognizer::ImageObjectRecognizer(std::shared_ptr<CocoDetector> coco,
                                             std::shared_ptr<const CnnClassifier> classifier,
                                             const repair::TypeOntology& ontology,
                                             const ObjectRecognitionOptions& options)
    : coco_(std::move(coco)), classifier_(std::move(classifier)), ontology_(&ontology), options_(options) {}

std::vector<ImageObject> ImageObjectRecognizer::recognize(const cv::Mat& bgr_image) {
  std::vector<ImageObject> found;
  const auto supertype = [&](const std::string& type) { return ontology_->parent(type).value_or(""); };
  if (coco_) {
    for (const ObjectDetection& d : coco_->detect(bgr_image)) {
      const auto mapped = options_.coco_to_type.find(std::string(d.label));
      if (mapped == options_.coco_to_type.end() || d.score < options_.coco_min_score) continue;
      found.push_back({mapped->second, supertype(mapped->second), d.score, "coco:" + std::string(d.label), d.box});
    }
  }
  if (found.empty() && classifier_) {
    const std::vector<float> scores = classifier_->scores(bgr_image);
    const auto best = static_cast<std::size_t>(std::max_element(scores.begin(), scores.end()) - scores.begin());
    if (scores[best] >= options_.classifier_min_score) {
      const std::string& type = classifier_->classes()[best];
      found.push_back({type, supertype(type), scores[best], "classifier", {}});
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const ImageObject& a, const ImageObject& b) { return a.score > b.score; });
  return found;
}

std::vector<std::string> ImageObjectRecognizer::perceivable_types() const {
  std::set<std::string> types;
  if (coco_) {
    for (const auto& [label, type] : options_.coco_to_type) types.insert(type);
  }
  if (classifier_) types.insert(classifier_->classes().begin(), classifier_->classes().end());
  return {types.begin(), types.end()};
}

}  // namespace alplan::perception
