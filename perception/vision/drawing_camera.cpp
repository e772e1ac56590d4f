#include "perception/vision/drawing_camera.h"

#include <algorithm>
#include <chrono>
#include <functional>

#include "perception/vision/cnn_runs.h"
#include "perception/vision/object_image_generator.h"

namespace alplan::perception {

TrainedObjectClassifier train_object_classifier_on_drawings(const DrawingCameraOptions& options) {
  const auto began = std::chrono::steady_clock::now();
  ObjectImageOptions images;
  images.per_class = options.images_per_class;
  images.seed = options.seed;
  const ImageDataset data = generate_object_images(images);
  CnnRunOptions run;
  run.architecture.channels = 3;
  run.training.epochs = options.epochs;
  run.training.threads = options.threads;
  run.training.seed = options.seed;
  run.seed = options.seed;
  auto [classifier, report] = train_and_test_cnn(data, run);
  TrainedObjectClassifier out;
  out.classifier = std::make_shared<const CnnClassifier>(std::move(classifier));
  out.test_accuracy = report.test.accuracy();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return out;
}

DrawingObjectRecognizer::DrawingObjectRecognizer(repair::ObjectRecognizer& truth,
                                                 std::shared_ptr<const CnnClassifier> classifier,
                                                 const repair::TypeOntology& ontology)
    : truth_(&truth), images_(nullptr, std::move(classifier), ontology) {}

std::vector<repair::RecognizedObject> DrawingObjectRecognizer::classify(
    const std::vector<repair::RecognizedObject>& truths) {
  const std::vector<std::string> drawable = drawable_object_classes();
  std::vector<repair::RecognizedObject> seen;
  for (const repair::RecognizedObject& thing : truths) {
    // A thing with no drawing cannot be pictured here: nothing is seen.
    if (std::find(drawable.begin(), drawable.end(), thing.type) == drawable.end()) continue;
    ObjectImageOptions picture;
    picture.per_class = 1;
    picture.classes = {thing.type};
    picture.seed = static_cast<unsigned>(std::hash<std::string>{}(thing.name));
    const ImageDataset one = generate_object_images(picture);
    const std::vector<ImageObject> named = images_.recognize(one.samples.front().image);
    if (named.empty()) continue;
    repair::RecognizedObject r = thing;
    r.type = named.front().type;
    r.confidence = named.front().score;
    seen.push_back(r);
  }
  return seen;
}

std::vector<repair::RecognizedObject> DrawingObjectRecognizer::recognize(const repair::WorldState& observed,
                                                                         const std::string& location) {
  return classify(truth_->recognize(observed, location));
}

std::vector<repair::RecognizedObject> DrawingObjectRecognizer::recognize_sightings(
    const std::vector<repair::Sighting>& sightings) {
  return classify(truth_->recognize_sightings(sightings));
}

}  // namespace alplan::perception
