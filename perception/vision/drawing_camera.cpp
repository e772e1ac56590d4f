#include "perception/vision/drawing_camera.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <functional>
#include <stdexcept>

#include "perception/common/model_cache.h"
#include "perception/vision/cnn_runs.h"
#include "perception/vision/object_image_generator.h"

namespace alplan::perception {

namespace {

// What the trained CNN depends on. Bump the version when the drawings, the
// architecture or the training change what is learned.
std::string cache_key(const DrawingCameraOptions& options) {
  constexpr int kVersion = 1;
  return "drawing-cnn v" + std::to_string(kVersion) + " per-class " + std::to_string(options.images_per_class) +
         " epochs " + std::to_string(options.epochs) + " threads " + std::to_string(options.threads) + " seed " +
         std::to_string(options.seed);
}

struct CnnWithAccuracy {
  CnnClassifier classifier;
  double test_accuracy = 0.0;
};

CnnWithAccuracy train_drawing_cnn(const DrawingCameraOptions& options) {
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
  return CnnWithAccuracy{std::move(classifier), report.test.accuracy()};
}

}  // namespace

TrainedObjectClassifier train_object_classifier_on_drawings(const DrawingCameraOptions& options) {
  const auto began = std::chrono::steady_clock::now();
  // The held-out accuracy travels beside the model, in a file of its own.
  const std::string name = model_cache_name("drawing-cnn", cache_key(options), ".pt");
  bool from_cache = false;
  CnnWithAccuracy model = cached_model<CnnWithAccuracy>(
      name, [&] { return train_drawing_cnn(options); },
      [](const std::filesystem::path& f) {
        std::ifstream in(f.string() + ".accuracy");
        double accuracy = -1.0;
        if (!(in >> accuracy) || accuracy < 0.0) throw std::runtime_error(f.string() + ": no accuracy beside it");
        return CnnWithAccuracy{CnnClassifier::load(f), accuracy};
      },
      [&name](const CnnWithAccuracy& m, const std::filesystem::path& f) {
        // Beside the final name (f is the temporary one the cache renames):
        // written before the model appears, so a model never lacks it.
        std::ofstream out(f.parent_path() / (name + ".accuracy"));
        out.precision(17);
        out << m.test_accuracy << "\n";
        m.classifier.save(f);
      },
      &from_cache);
  TrainedObjectClassifier out;
  out.classifier = std::make_shared<const CnnClassifier>(std::move(model.classifier));
  out.test_accuracy = model.test_accuracy;
  out.from_cache = from_cache;
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
