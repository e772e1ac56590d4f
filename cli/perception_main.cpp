// The perception module's entry point (perception_module.h): the same
// command line `alplan` received, parsed here with the perception commands.
#include <CLI/CLI.hpp>

#include <opencv2/core/utils/logger.hpp>

#include <exception>
#include <memory>

#include "cli/commands.h"
#include "cli/parse_command_line.h"
#include "cli/perception_module.h"
#include "perception/vision/drawing_camera.h"

extern "C" __attribute__((visibility("default"))) int alplan_perception_main(int argc, char** argv) {
  // OpenCV's own warnings ("can't open/read file") would repeat the
  // commands' errors in another voice.
  cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_ERROR);
  CLI::App app{"alplan: PDDL 2.2 temporal planning toolkit for assisted-living deliberation"};
  app.require_subcommand(1);
  // Every option's help shows its default (subcommands inherit this).
  app.option_defaults()->always_capture_default();
  int exit_code = alplan::cli::kExitOk;
  alplan::cli::add_perceive_command(app, exit_code);
  alplan::cli::add_deliberate_command(app, exit_code);
  alplan::cli::add_serve_command(app, exit_code);
  alplan::cli::add_wristband_command(app, exit_code);
  alplan::cli::add_home_command(app, exit_code);
  CLI::App* bench = app.add_subcommand("bench", "Benchmarks");
  bench->require_subcommand(1);
  alplan::cli::add_bench_service_command(bench, exit_code);
  alplan::cli::add_bench_soak_command(bench, exit_code);
  alplan::cli::add_bench_home_command(bench, exit_code);
  return alplan::cli::parse_command_line(app, argc, argv, exit_code);
}

// The repair study's camera (perception_module.h): trains the CNN once.
extern "C" __attribute__((visibility("default"))) bool alplan_drawing_camera(const char* types_ttl,
                                                                             alplan::cli::ObjectCamera* make,
                                                                             nlohmann::json* info, std::string* error) {
  try {
    auto ontology = std::make_shared<const alplan::repair::TypeOntology>(alplan::repair::TypeOntology::from_file(types_ttl));
    const alplan::perception::TrainedObjectClassifier trained = alplan::perception::train_object_classifier_on_drawings({});
    *info = {{"recognizer", "the paper's CNN on drawings of each thing's true type"},
             {"classifier_test_accuracy", trained.test_accuracy},
             {"training_seconds", trained.seconds},
             {"model_from_cache", trained.from_cache}};
    *make = [ontology, classifier = trained.classifier](alplan::repair::ObjectRecognizer& truth) {
      return std::unique_ptr<alplan::repair::ObjectRecognizer>(
          std::make_unique<alplan::perception::DrawingObjectRecognizer>(truth, classifier, *ontology));
    };
    return true;
  } catch (const std::exception& e) {
    *error = e.what();
    return false;
  }
}
