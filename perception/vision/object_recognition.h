// Object recognition for the planning domain (the paper's Section 6.2 and
// its Table 4): what objects an image shows, named by the domain's
// (augmented) types, with their supertype.
//
// Two recognisers are combined, each for what it knows:
//  - the pretrained COCO detector (real photographs: CenterNet trained on
//    COCO) for the classes COCO has and the domain uses: cup -> cup,
//    wine glass -> drinking_glass, bottle -> glass_bottle, book -> book;
//  - the project's CNN (cnn_classifier.h) trained on the augmented types,
//    for the classes no shipped model knows (mug, jar, clarinet, drum,
//    sudoku, ...). Trained here on generated images
//    (object_image_generator.h) unless the user trains it on photographs.
// A COCO detection of a mapped class above its threshold is reported with
// its box; otherwise the CNN's answer for the whole image, if it is
// confident enough. The supertype comes from the type ontology.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "perception/vision/cnn_classifier.h"
#include "perception/vision/coco_detector.h"
#include "repair/type_ontology.h"

namespace alplan::perception {

struct ImageObject {
  std::string type;       // a domain type, e.g. "cup"
  std::string supertype;  // its parent in the ontology, e.g. "drinking_vessel"
  float score = 0.0f;
  std::string source;     // "coco:cup" or "classifier"
  cv::Rect2f box;         // empty for the classifier's whole-image answer
};

struct ObjectRecognitionOptions {
  float coco_min_score = 0.3f;
  float classifier_min_score = 0.6f;
  std::map<std::string, std::string> coco_to_type = {
      {"cup", "cup"}, {"wine glass", "drinking_glass"}, {"bottle", "glass_bottle"}, {"book", "book"}};
};

class ImageObjectRecognizer {
 public:
  // Either recogniser may be null (then only the other is used); the
  // ontology must outlive this object.
  ImageObjectRecognizer(std::shared_ptr<CocoDetector> coco, std::shared_ptr<const CnnClassifier> classifier,
                        const repair::TypeOntology& ontology, const ObjectRecognitionOptions& options = {});

  // Best first.
  std::vector<ImageObject> recognize(const cv::Mat& bgr_image);

  // The classes some recogniser can name (for types augmentation: a type
  // nobody can see is no use to the planner).
  std::vector<std::string> perceivable_types() const;

 private:
  std::shared_ptr<CocoDetector> coco_;
  std::shared_ptr<const CnnClassifier> classifier_;
  const repair::TypeOntology* ontology_;
  ObjectRecognitionOptions options_;
};

}  // namespace alplan::perception
