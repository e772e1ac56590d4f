#include "cli/deliberation_run.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include <opencv2/imgcodecs.hpp>

#include "cli/commands.h"
#include "cli/paper_format.h"
#include "cli/perceive_common.h"
#include "domains/mission_run.h"
#include "perception/deliberation.h"
#include "perception/vision/camera_object_recognizer.h"
#include "perception/vision/pretrained_emotion_recognizer.h"

namespace alplan::cli {
namespace {

std::vector<repair::ExogenousEvent> scripted_events(const std::vector<std::string>& specs) {
  std::vector<repair::ExogenousEvent> events;
  for (const std::string& spec : specs) {
    const std::size_t at = spec.find('@');
    double time = 0;
    try {
      if (at == std::string::npos) throw std::invalid_argument("no @");
      time = std::stod(spec.substr(at + 1));
    } catch (const std::exception&) {
      throw CommandInputError("--unavailable " + spec + ": expected OBJECT@TIME, e.g. glass_id05@140");
    }
    events.push_back(repair::becomes_unavailable(time, spec.substr(0, at)));
  }
  return events;
}

void print_mission(const domains::MissionRun& run) {
  std::cout << "\n[plan] the initial plan:\n" << paper_format(run.initial_plan) << "\n";
  for (const std::string& e : run.report.events) std::cout << "  " << e << "\n";
  for (const repair::RepairRecord& r : run.report.repairs) {
    for (const repair::RecognizedObject& seen : r.integrated) {
      std::cout << "\n[perception] the camera saw " << seen.name << " (" << seen.type << ") at " << seen.location << "\n";
    }
    if (!r.repaired) {
      std::cout << (r.deferred ? "\nNo repair yet (" : "\nFailed repair (") << r.strategy << "):\n" << r.explanation.text();
      continue;
    }
    std::cout << "\nRepaired plan (" << r.strategy << "):\n" << paper_format(r.plan_text) << "\n" << r.explanation.text();
  }
  std::cout << "\nOutcome: " << run.report.outcome << "\n";
}

}  // namespace

void add_deliberation_options(CLI::App& cmd, DeliberationSettings& s) {
  cmd.add_option("--domains-dir", s.dir, "Folder with domain.pddl, types.ttl and the problems");
  cmd.add_option("--problem", s.problem, "The home's problem file in that folder (its goal is replaced)");
  cmd.add_option("--face", s.face, "An image of the senior's face (the pretrained emotion network reads it)");
  cmd.add_option("--emotion", s.emotion, "The emotion, when no face image is at hand (said to be given)");
  cmd.add_option("--looks", s.looks, "Times the robot looks at the face (the boredom rule needs repeated neutral looks)");
  cmd.add_option("--camera", s.camera, "Folder with a subfolder of images per location: what the robot's camera sees");
  cmd.add_option("--unavailable", s.unavailable, "OBJECT@TIME: the object becomes unavailable then (repeatable)");
  cmd.add_option("--strategy", s.strategy, "Repair strategy: replan, substitute, suggest, patch, adapt");
}

Deliberator::Deliberator(DeliberationSettings settings)
    : settings_(std::move(settings)),
      home_(domains::load_home(settings_.dir, settings_.problem)),
      unavailable_(scripted_events(settings_.unavailable)) {
  if (settings_.emotion.empty() && settings_.face.empty()) {
    throw CommandInputError("give the seniors' face (--face IMAGE) or the emotion (--emotion NAME)");
  }
  if (!settings_.emotion.empty() && !perception::emotion_from_name(settings_.emotion)) {
    throw CommandInputError("--emotion " + settings_.emotion + ": not an emotion (terrified, sad, bored, happy, ...)");
  }
  if (settings_.emotion.empty()) faces_ = std::make_unique<perception::PretrainedEmotionRecognizer>();
  if (!settings_.camera.empty()) {
    if (!std::filesystem::is_directory(settings_.camera)) {
      throw CommandInputError(settings_.camera + ": not a folder of camera views");
    }
    images_ = std::make_unique<perception::ImageObjectRecognizer>(std::make_shared<perception::CocoDetector>(), nullptr,
                                                                  home_.ontology);
  }
}

std::optional<perception::EmotionReading> Deliberator::emotion() {
  const DeliberationSettings& o = settings_;
  if (!o.emotion.empty()) {
    const perception::Emotion e = *perception::emotion_from_name(o.emotion);
    std::printf("[emotion] given on the command line: %s\n", std::string(perception::emotion_name(e)).c_str());
    return perception::EmotionReading{e, 1.0f, true};
  }
  // The face is read at every event: it is what the robot sees now.
  if (!std::filesystem::is_regular_file(o.face)) throw CommandInputError(o.face + ": no such file");
  const cv::Mat image = cv::imread(o.face, cv::IMREAD_COLOR);
  if (image.empty()) throw CommandInputError(o.face + ": cannot read an image from this file");
  const auto reading = perception::read_face(*faces_, image, false);
  if (!reading) {
    std::printf("[emotion] no face in %s\n", o.face.c_str());
  } else {
    std::printf("[emotion] face in %s: %s %.3f\n", o.face.c_str(), std::string(perception::emotion_name(reading->top)).c_str(),
                static_cast<double>(reading->score));
  }
  return reading;
}

int Deliberator::on_stress(const std::string& senior, const perception::StressState& stress) {
  const DeliberationSettings& o = settings_;
  // Layer 2: emotion and goal.
  const auto emotion = this->emotion();
  if (!emotion) return kExitOk;
  perception::EmotionGoalGenerator generator;
  std::optional<perception::GeneratedGoal> goal;
  for (int look = 0; look < std::max(1, o.looks) && !goal; ++look) goal = generator.generate(senior, stress, *emotion);
  if (!goal) {
    std::printf("[goal] none: %s generates no goal for a stressed senior\n", std::string(perception::emotion_name(emotion->top)).c_str());
    return kExitOk;
  }
  std::printf("[goal] (%s %s): %s, decided by %s\n", goal->goal.atom.name.c_str(), senior.c_str(), goal->motivation.c_str(),
              goal->decided_by.c_str());

  // Layers 3 and 4: plan, act, monitor, repair.
  domains::MissionInput input;
  input.domain = &home_.domain;
  input.problem = perception::reformulate_for_goal(*home_.files.problem, *goal, 0.0);
  input.events = unavailable_;
  input.motivation = goal->motivation;
  input.seniors = {senior};
  input.ontology = &home_.ontology;
  // A new camera recogniser per run: the names it gives belong to one mission.
  std::unique_ptr<perception::FolderCamera> camera;
  std::unique_ptr<perception::CameraObjectRecognizer> eyes;
  if (images_) {
    camera = std::make_unique<perception::FolderCamera>(o.camera);
    eyes = std::make_unique<perception::CameraObjectRecognizer>(*camera, *images_);
    input.recognizer = eyes.get();
    // What the views show is really there: the simulated world gets those
    // objects from the start (no IoT sensor reports them, so the planner
    // knows them only once the camera is asked). The recogniser remembers
    // the names it gives, so the monitor's look later names them alike.
    const repair::WorldState before = repair::initial_world(input.problem);
    for (const auto& entry : std::filesystem::directory_iterator(o.camera)) {
      if (!entry.is_directory()) continue;
      for (const repair::RecognizedObject& seen : eyes->recognize(before, entry.path().filename().string())) {
        input.events.push_back(repair::object_appears(0.0, seen));
      }
    }
  }
  domains::ScenarioOptions options;
  options.assisted_living_dir = o.dir;
  options.strategy = o.strategy;
  try {
    const domains::MissionRun run = domains::run_mission(input, options);
    print_mission(run);
    return run.report.goal_reached ? kExitOk : kExitInvalid;
  } catch (const domains::NoInitialPlan& e) {
    // Deliberation ends here, explained: the goal perception chose has no
    // plan in this home, so the robot does nothing rather than fail.
    std::cout << "\n[plan] no plan: " << e.what() << "\n[outcome] the robot cannot comfort "
              << input.seniors.front() << " in this home: " << input.motivation << "\n";
    return kExitInvalid;
  }
}

}  // namespace alplan::cli
