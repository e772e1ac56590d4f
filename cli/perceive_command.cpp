// alplan perceive emotion IMAGE | objects IMAGE | ontology | stress ... |
// trainer-check: the perception layer from the command line. Runs in the
// perception module (perception_module.h). Exit 0 on success, 1 when a
// check fails, 2 on bad input.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli/commands.h"
#include "cli/perceive_common.h"
#include "pddl_parser/parser.h"
#include "perception/goals/goal_generator.h"
#include "perception/ontology/type_augmentation.h"
#include "perception/vision/cnn_emotion_recognizer.h"
#include "perception/vision/coco_labels.h"
#include "perception/vision/object_image_generator.h"
#include "perception/vision/object_recognition.h"
#include "perception/vision/pretrained_emotion_recognizer.h"

namespace alplan::cli {
namespace {

struct ImageCommandOptions {
  std::string image;
  std::string model;       // a trained CNN instead of / besides the pretrained one
  std::string ontology = std::string(ALPLAN_ASSISTED_LIVING_DIR) + "/types.ttl";
  bool json = false;
};

cv::Mat read_image_or_fail(const std::string& path) {
  if (path.empty()) throw CommandInputError("an IMAGE is required (or a subcommand: train, evaluate)");
  if (!std::filesystem::is_regular_file(path)) throw CommandInputError(path + ": no such file");
  cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) throw CommandInputError(path + ": cannot read an image from this file");
  return image;
}

int run_emotion(const ImageCommandOptions& o) {
  const cv::Mat image = read_image_or_fail(o.image);
  std::unique_ptr<perception::EmotionRecognizer> recognizer;
  bool scores_bored = false;
  if (o.model.empty()) {
    recognizer = std::make_unique<perception::PretrainedEmotionRecognizer>();
  } else {
    auto cnn = std::make_unique<perception::CnnEmotionRecognizer>(
        std::make_shared<const perception::CnnClassifier>(perception::CnnClassifier::load(o.model)));
    scores_bored = cnn->scores_bored();
    recognizer = std::move(cnn);
  }
  const std::vector<perception::FaceEmotion> faces = recognizer->recognize(image);
  nlohmann::json out = {{"image", o.image}, {"faces", nlohmann::json::array()}};
  if (!o.json) std::cout << o.image << ": " << faces.size() << (faces.size() == 1 ? " face\n" : " faces\n");
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const perception::FaceEmotion& f = faces[i];
    const auto goal = perception::goal_predicate(f.label);
    nlohmann::json scores = nlohmann::json::object();
    for (const auto& [e, s] : f.scores) scores[std::string(perception::emotion_name(e))] = s;
    out["faces"].push_back({{"box", {f.face.x, f.face.y, f.face.width, f.face.height}},
                            {"label", perception::emotion_name(f.label)},
                            {"score", f.score},
                            {"scores", scores},
                            {"goal_if_stressed", goal ? std::string(*goal) : std::string()}});
    if (o.json) continue;
    std::printf("face %zu at (%d, %d) %dx%d: %s %.3f\n", i + 1, f.face.x, f.face.y, f.face.width, f.face.height,
                std::string(perception::emotion_name(f.label)).c_str(), static_cast<double>(f.score));
    std::string line = "  scores:";
    for (const auto& [e, s] : f.scores) {
      char cell[48];
      std::snprintf(cell, sizeof cell, " %s %.3f", std::string(perception::emotion_name(e)).c_str(), static_cast<double>(s));
      line += cell;
    }
    std::cout << line << "\n  if the senior is stressed: "
              << (goal ? "goal (" + std::string(*goal) + " <senior>)" : std::string("no goal for this emotion")) << "\n";
  }
  if (!o.json && !scores_bored) {
    std::cout << "(this model has no bored class: goal generation decides boredom by its rule, "
                 "perception/goals/goal_generator.h)\n";
  }
  if (o.json) std::cout << out.dump(2) << "\n";
  return kExitOk;
}

int run_objects(const ImageCommandOptions& o) {
  const cv::Mat image = read_image_or_fail(o.image);
  const repair::TypeOntology ontology = repair::TypeOntology::from_file(o.ontology);
  std::shared_ptr<const perception::CnnClassifier> classifier;
  if (!o.model.empty()) {
    classifier = std::make_shared<const perception::CnnClassifier>(perception::CnnClassifier::load(o.model));
  }
  perception::ImageObjectRecognizer recognizer(std::make_shared<perception::CocoDetector>(), classifier, ontology);
  const std::vector<perception::ImageObject> found = recognizer.recognize(image);
  nlohmann::json out = {{"image", o.image}, {"objects", nlohmann::json::array()}};
  for (const perception::ImageObject& f : found) {
    out["objects"].push_back({{"type", f.type}, {"supertype", f.supertype}, {"score", f.score}, {"source", f.source},
                              {"box", {f.box.x, f.box.y, f.box.width, f.box.height}}});
    if (o.json) continue;
    std::printf("%s (%s) %.3f [%s]", f.type.c_str(), f.supertype.empty() ? "?" : f.supertype.c_str(),
                static_cast<double>(f.score), f.source.c_str());
    if (f.box.area() > 0) {
      std::printf(" at (%.0f, %.0f) %.0fx%.0f", static_cast<double>(f.box.x), static_cast<double>(f.box.y),
                  static_cast<double>(f.box.width), static_cast<double>(f.box.height));
    }
    std::printf("\n");
  }
  if (o.json) {
    std::cout << out.dump(2) << "\n";
  } else if (found.empty()) {
    std::cout << o.image << ": no object of a domain type"
              << (classifier ? "" : " (COCO's cup, wine glass, bottle and book; give --classifier for the others)") << "\n";
  }
  return kExitOk;
}

struct OntologyCommandOptions {
  std::string domain = std::string(ALPLAN_ASSISTED_LIVING_DIR) + "/domain.pddl";
  std::string config = std::string(ALPLAN_ASSISTED_LIVING_DIR) + "/augmentation.txt";
  std::string wordnet = "/usr/share/wordnet";
  std::string perceivable = "recognisers";
  int max_per_type = 3;
  int max_depth = 5;
  std::string out;
  bool explain = false;
  bool json = false;
};

std::set<std::string> perceivable_vocabulary(const std::string& choice) {
  if (choice == "all") return {};
  if (choice == "recognisers") {
    std::set<std::string> names;
    for (const auto& [label, type] : perception::ObjectRecognitionOptions{}.coco_to_type) names.insert(type);
    for (const std::string& c : perception::drawable_object_classes()) names.insert(c);
    return names;
  }
  std::ifstream in(choice);
  if (!in) throw CommandInputError(choice + ": cannot read the perceivable classes (all, recognisers or a file)");
  std::set<std::string> names;
  for (std::string word; in >> word;) names.insert(word);
  return names;
}

int run_ontology(const OntologyCommandOptions& o) {
  std::string text;
  std::vector<pddl::Diagnostic> diagnostics;
  if (!pddl::read_file(o.domain, text, diagnostics)) throw CommandInputError(o.domain + ": cannot read the domain");
  const auto parsed = pddl::parse_domain(text, o.domain);
  if (!parsed.ok()) throw CommandInputError(o.domain + ": the domain has errors (alplan parse shows them)");
  std::ifstream config_file(o.config);
  if (!config_file) throw CommandInputError(o.config + ": cannot read the category configuration");
  const std::string config((std::istreambuf_iterator<char>(config_file)), std::istreambuf_iterator<char>());

  perception::AugmentationOptions options;
  options.max_new_per_type = o.max_per_type;
  options.max_depth = o.max_depth;
  options.perceivable = perceivable_vocabulary(o.perceivable);
  const perception::TypeParents types = perception::type_parents(*parsed.ast);
  const perception::AugmentationResult result = perception::augment_types(
      perception::WordNet::load_nouns(o.wordnet), types, perception::read_category_config(config, o.config), options);
  const std::string turtle = perception::augmented_ontology_turtle(types, result);
  if (!o.out.empty()) {
    std::ofstream(o.out) << turtle;
    if (!o.json) std::cout << "wrote " << o.out << "\n";
  }
  print_ontology(types, result, o.explain, o.json);
  return kExitOk;
}

}  // namespace

void add_perceive_command(CLI::App& app, int& exit_code) {
  CLI::App* perceive = app.add_subcommand("perceive", "Perception: emotions, objects, the type ontology, stress");
  perceive->require_subcommand(1);

  auto image = std::make_shared<ImageCommandOptions>();
  CLI::App* emotion = perceive->add_subcommand("emotion", "Faces in an image, each with its emotion and scores");
  emotion->add_option("image", image->image, "An image file (PNG, JPEG, ...)");
  emotion->add_option("--model", image->model, "A CNN trained with 'perceive emotion train' (default: pretrained mini-Xception)");
  emotion->add_flag("--json", image->json, "Print JSON");
  add_emotion_learning_commands(*emotion, exit_code);
  emotion->callback([emotion, image, &exit_code] {
    if (emotion->get_subcommands().empty()) exit_code = guarded([&] { return run_emotion(*image); }, image->image);
  });

  auto objects_options = std::make_shared<ImageCommandOptions>();
  CLI::App* objects = perceive->add_subcommand("objects", "Objects of the domain's types in an image: type, supertype, score");
  objects->add_option("image", objects_options->image, "An image file");
  objects->add_option("--classifier", objects_options->model, "An object CNN trained with 'perceive objects train'");
  objects->add_option("--ontology", objects_options->ontology, "The type ontology (Turtle)");
  objects->add_flag("--json", objects_options->json, "Print JSON");
  add_object_learning_commands(*objects, exit_code);
  objects->callback([objects, objects_options, &exit_code] {
    if (objects->get_subcommands().empty()) {
      exit_code = guarded([&] { return run_objects(*objects_options); }, objects_options->image);
    }
  });

  auto onto = std::make_shared<OntologyCommandOptions>();
  CLI::App* ontology = perceive->add_subcommand("ontology", "Augment the domain's types from WordNet; print supertype -> subtypes");
  ontology->add_option("--domain", onto->domain, "The PDDL domain whose types are augmented");
  ontology->add_option("--config", onto->config, "Categories to augment and their WordNet senses");
  ontology->add_option("--wordnet", onto->wordnet, "WordNet's dict folder (Debian wordnet-base)");
  ontology->add_option("--perceivable", onto->perceivable, "Keep types a recogniser can see: recognisers (default), all, or a file of names");
  ontology->add_option("--max-per-type", onto->max_per_type, "New types per category")->check(CLI::PositiveNumber);
  ontology->add_option("--max-depth", onto->max_depth, "Hyponym levels below an anchor")->check(CLI::PositiveNumber);
  ontology->add_option("--out", onto->out, "Write the augmented ontology (OWL in Turtle) here");
  ontology->add_flag("--explain", onto->explain, "Show anchors, rules and what was passed over");
  ontology->add_flag("--json", onto->json, "Print JSON");
  ontology->callback([onto, &exit_code] { exit_code = guarded([&] { return run_ontology(*onto); }, onto->domain); });

  add_perceive_stress_command(*perceive, exit_code);
  add_trainer_check_command(*perceive, exit_code);
}

}  // namespace alplan::cli
