#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include <opencv2/imgcodecs.hpp>

#include "perception/vision/camera_object_recognizer.h"
#include "perception/vision/cnn_classifier.h"
#include "perception/vision/object_image_generator.h"
#include "perception/vision/object_recognition.h"
#include "repair/type_ontology.h"
#include "tests/support/test_paths.h"

using namespace alplan::perception;
namespace fs = std::filesystem;

namespace {

const std::string kSkimage = "/usr/lib/python3/dist-packages/skimage/data/";

alplan::repair::TypeOntology paper_ontology() {
  return alplan::repair::TypeOntology::from_file(alplan::test::source_dir() + "/domains/assisted_living/types.ttl");
}

// A small object classifier trained on generated images (a few seconds).
std::shared_ptr<const CnnClassifier> small_object_classifier(const std::vector<std::string>& classes) {
  ObjectImageOptions images;
  images.per_class = 60;
  images.size = 48;
  images.classes = classes;
  images.seed = 3;
  CnnArchitecture architecture;
  architecture.channels = 3;
  auto model = std::make_shared<CnnClassifier>(classes, architecture);
  TrainingOptions training;
  training.epochs = 12;
  training.patience = 12;
  training.learning_rate = 2e-3;
  model->train(generate_object_images(images), training);
  return model;
}

}  // namespace

TEST_CASE("generated object images: every class of Table 4, deterministic for a seed") {
  ObjectImageOptions options;
  options.per_class = 3;
  const ImageDataset a = generate_object_images(options);
  CHECK(a.classes.size() == 18);
  CHECK(a.samples.size() == 54);
  CHECK(a.samples.front().image.size() == cv::Size(64, 64));
  CHECK(a.samples.front().image.type() == CV_8UC3);
  const ImageDataset b = generate_object_images(options);
  CHECK(cv::norm(a.samples[7].image, b.samples[7].image, cv::NORM_INF) == 0);
  options.seed = 2;
  CHECK(cv::norm(a.samples[7].image, generate_object_images(options).samples[7].image, cv::NORM_INF) > 0);
  // Each class is named as the ontology (the domain and Fig. 5) names it.
  const auto ontology = paper_ontology();
  for (const std::string& c : a.classes) CHECK(ontology.parent(c).has_value());
  options.classes = {"spaceship"};
  CHECK_THROWS_WITH(generate_object_images(options), Catch::Contains("no drawing for object class 'spaceship'"));
}

TEST_CASE("a real photograph of a cup is recognised as a drinking vessel by the pretrained detector") {
  const auto ontology = paper_ontology();
  ImageObjectRecognizer recognizer(std::make_shared<CocoDetector>(), nullptr, ontology);
  const std::vector<ImageObject> found = recognizer.recognize(cv::imread(kSkimage + "coffee.png"));
  REQUIRE_FALSE(found.empty());
  CHECK(found.front().type == "cup");
  CHECK(found.front().supertype == "drinking_vessel");
  CHECK(found.front().source == "coco:cup");
  CHECK(found.front().box.area() > 0);
  // A photo of an astronaut holds nothing the robot could bring.
  CHECK(recognizer.recognize(cv::imread(kSkimage + "astronaut.png")).empty());
}

TEST_CASE("the classifier names the classes no shipped model knows, and the camera turns them into new objects") {
  const std::vector<std::string> classes = {"clarinet", "drum", "mug", "sudoku"};
  const auto classifier = small_object_classifier(classes);
  ObjectImageOptions unseen;
  unseen.per_class = 25;
  unseen.size = 48;
  unseen.classes = classes;
  unseen.seed = 99;  // images the classifier never saw
  const ConfusionMatrix matrix = classifier->evaluate(generate_object_images(unseen));
  INFO(matrix.markdown());
  CHECK(matrix.accuracy() > 0.8);  // chance is 0.25

  const auto ontology = paper_ontology();
  ImageObjectRecognizer recognizer(nullptr, classifier, ontology);
  CHECK(recognizer.perceivable_types() == classes);
  const fs::path dir = fs::temp_directory_path() / "alplan-camera";
  fs::remove_all(dir);
  fs::create_directories(dir / "music_room1");
  unseen.per_class = 1;
  unseen.classes = {"clarinet"};
  REQUIRE(cv::imwrite((dir / "music_room1" / "view.png").string(), generate_object_images(unseen).samples[0].image));

  FolderCamera camera(dir.string());
  CameraObjectRecognizer eyes(camera, recognizer);
  alplan::repair::WorldState observed;
  observed.atoms.insert({"be", "clarinet_id01", "library1"});  // the name is taken
  const auto objects = eyes.recognize(observed, "music_room1");
  REQUIRE(objects.size() == 1);
  CHECK(objects[0].type == "clarinet");
  CHECK(objects[0].name == "clarinet_id02");
  CHECK(objects[0].location == "music_room1");
  // Looking again sees the same object, not a new one.
  CHECK(eyes.recognize(observed, "music_room1")[0].name == "clarinet_id02");
  CHECK(eyes.recognize(observed, "kitchen1").empty());
}

TEST_CASE("a CNN survives a save and a load, foreign files are refused") {
  const std::vector<std::string> classes = {"book", "cup"};
  CnnArchitecture architecture;
  architecture.channels = 3;
  CnnClassifier model(classes, architecture);
  ObjectImageOptions images;
  images.per_class = 4;
  images.size = 48;
  images.classes = classes;
  const ImageDataset data = generate_object_images(images);
  const fs::path file = fs::temp_directory_path() / "alplan-cnn.pt";
  model.save(file);
  const CnnClassifier loaded = CnnClassifier::load(file);
  CHECK(loaded.classes() == classes);
  CHECK(loaded.architecture().channels == 3);
  const auto before = model.scores(data.samples[0].image);
  const auto after = loaded.scores(data.samples[0].image);
  for (std::size_t i = 0; i < before.size(); ++i) CHECK(after[i] == Approx(before[i]).margin(1e-6));

  const fs::path junk = fs::temp_directory_path() / "alplan-not-a-model.pt";
  { std::ofstream(junk) << "not a model"; }
  CHECK_THROWS_AS(CnnClassifier::load(junk), ModelFileError);
  CHECK_THROWS_AS(CnnClassifier(std::vector<std::string>{"only"}, architecture), std::invalid_argument);
  architecture.kernel = 2;
  CHECK_THROWS_WITH(CnnClassifier(classes, architecture), Catch::Contains("odd"));
}
