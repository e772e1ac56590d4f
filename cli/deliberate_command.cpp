// alplan deliberate: the paper's deliberation for one senior, end to end —
// the wristband's PPG (a CSV recording, or the simulator's) through the
// stress detector; on a stress event the senior's face through the emotion
// recogniser; the emotion to a goal; the goal into the planning problem;
// plan, execute, monitor and repair, with the robot's camera (a folder of
// images per location) as the object recogniser. Exit 0 when the senior is
// comforted or nothing needed doing, 1 when the run ends with an explained
// failure, 2 on bad input.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cli/commands.h"
#include "cli/paper_format.h"
#include "cli/perceive_common.h"
#include "domains/mission_run.h"
#include "domains/pddl_files.h"
#include "perception/camera_object_recognizer.h"
#include "perception/deliberation.h"
#include "perception/learning_runs.h"
#include "perception/pretrained_emotion_recognizer.h"

namespace alplan::cli {
namespace {

struct DeliberateOptions {
  std::string dir = ALPLAN_ASSISTED_LIVING_DIR;
  std::string problem = "paper-scenario-1.pddl";
  std::string senior = "senior1";
  std::string ppg;
  double calm_s = 60, stressed_s = 120;
  bool calm_only = false;
  std::uint64_t seed = 7;
  std::string stress_model;
  std::string face;
  std::string emotion;
  int looks = 3;
  std::string camera;
  std::vector<std::string> unavailable;  // OBJECT@TIME
  std::string strategy = "substitute";
};

// The simulator's senior: calm, then (unless calm_only) stressed, as one
// recording.
perception::PpgRecording simulated_senior(const DeliberateOptions& o) {
  perception::PpgSimulator simulator(o.seed);
  const perception::SubjectProfile calm = simulator.random_subject();
  perception::RecordingConditions conditions;
  conditions.sample_rate_hz = 50;
  conditions.duration_s = o.calm_s;
  perception::PpgRecording out = simulator.simulate(calm, conditions).recording;
  if (o.calm_only) return out;
  conditions.duration_s = o.stressed_s;
  const perception::PpgRecording later =
      simulator.simulate(perception::under_stress(calm, simulator.random_stress_response()), conditions).recording;
  const double offset = out.time_s.back() + 1.0 / conditions.sample_rate_hz;
  for (std::size_t i = 0; i < later.size(); ++i) {
    out.time_s.push_back(offset + later.time_s[i]);
    out.ppg.push_back(later.ppg[i]);
  }
  return out;
}

perception::StressClassifier stress_model(const DeliberateOptions& o) {
  if (!o.stress_model.empty()) return perception::StressClassifier::load(o.stress_model);
  perception::DatabaseSpec spec;
  spec.subjects = 24;
  spec.recordings_per_state = 1;
  spec.conditions.duration_s = 150;
  spec.conditions.sample_rate_hz = 50;
  spec.seed = o.seed + 1;  // not the senior's own recordings
  std::vector<perception::StressExample> examples;
  for (const auto& s : perception::windows_by_subject(perception::generate_labelled_database(spec), perception::StressFeatureSet::Paper)) {
    examples.insert(examples.end(), s.examples.begin(), s.examples.end());
  }
  std::printf("[learning] stress model trained on the simulated database (24 subjects; --stress-model to load one)\n");
  return perception::StressClassifier::train(examples, {});
}

std::optional<perception::EmotionReading> emotion_of(const DeliberateOptions& o) {
  if (!o.emotion.empty()) {
    const auto e = perception::emotion_from_name(o.emotion);
    if (!e) throw CommandInputError("--emotion " + o.emotion + ": not an emotion (terrified, sad, bored, happy, ...)");
    std::printf("[emotion] given on the command line: %s\n", std::string(perception::emotion_name(*e)).c_str());
    return perception::EmotionReading{*e, 1.0f, true};
  }
  if (o.face.empty()) throw CommandInputError("give the senior's face (--face IMAGE) or the emotion (--emotion NAME)");
  if (!std::filesystem::is_regular_file(o.face)) throw CommandInputError(o.face + ": no such file");
  const cv::Mat image = cv::imread(o.face, cv::IMREAD_COLOR);
  if (image.empty()) throw CommandInputError(o.face + ": cannot read an image from this file");
  perception::PretrainedEmotionRecognizer recognizer;
  const auto reading = perception::read_face(recognizer, image, false);
  if (!reading) {
    std::printf("[emotion] no face in %s\n", o.face.c_str());
  } else {
    std::printf("[emotion] face in %s: %s %.3f\n", o.face.c_str(), std::string(perception::emotion_name(reading->top)).c_str(),
                static_cast<double>(reading->score));
  }
  return reading;
}

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
      std::cout << "\nFailed repair (" << r.strategy << "):\n" << r.explanation.text();
      continue;
    }
    std::cout << "\nRepaired plan (" << r.strategy << "):\n" << paper_format(r.plan_text) << "\n" << r.explanation.text();
  }
  std::cout << "\nOutcome: " << run.report.outcome << "\n";
}

int run(const DeliberateOptions& o) {
  const domains::LoadedFiles files = domains::load_pddl(o.dir + "/domain.pddl", o.dir + "/" + o.problem);
  const repair::TypeOntology ontology = repair::TypeOntology::from_file(o.dir + "/types.ttl");
  const pddl::Domain domain = repair::augment_domain(*files.domain, ontology);

  // Layer 1: stress.
  const perception::PpgRecording ppg = o.ppg.empty() ? simulated_senior(o) : perception::read_ppg_csv_file(o.ppg);
  perception::ClassifierStressDetector detector(stress_model(o), {});
  const auto event = perception::first_stress_event(detector, o.senior, perception::stress_windows(ppg));
  if (!event) {
    std::printf("[stress] %s's wristband: not stressed over %.0f s of readings; nothing to do\n", o.senior.c_str(),
                ppg.time_s.empty() ? 0.0 : ppg.time_s.back());
    return kExitOk;
  }
  std::printf("[stress] %s's wristband: stressed at %.0f s (%zu of the last %zu readings say so): stress event\n",
              o.senior.c_str(), event->time_s, static_cast<std::size_t>(event->state.stressed_fraction * static_cast<double>(event->state.votes) + 0.5),
              event->state.votes);

  // Layer 2: emotion and goal.
  const auto emotion = emotion_of(o);
  if (!emotion) return kExitOk;
  perception::EmotionGoalGenerator generator;
  std::optional<perception::GeneratedGoal> goal;
  for (int look = 0; look < std::max(1, o.looks) && !goal; ++look) goal = generator.generate(o.senior, event->state, *emotion);
  if (!goal) {
    std::printf("[goal] none: %s generates no goal for a stressed senior\n", std::string(perception::emotion_name(emotion->top)).c_str());
    return kExitOk;
  }
  std::printf("[goal] (%s %s): %s, decided by %s\n", goal->goal.atom.name.c_str(), o.senior.c_str(), goal->motivation.c_str(),
              goal->decided_by.c_str());

  // Layers 3 and 4: plan, act, monitor, repair.
  domains::MissionInput input;
  input.domain = &domain;
  input.problem = perception::reformulate_for_goal(*files.problem, *goal, 0.0);
  input.events = scripted_events(o.unavailable);
  input.motivation = goal->motivation;
  input.seniors = {o.senior};
  input.ontology = &ontology;
  std::unique_ptr<perception::FolderCamera> camera;
  std::unique_ptr<perception::ImageObjectRecognizer> images;
  std::unique_ptr<perception::CameraObjectRecognizer> eyes;
  if (!o.camera.empty()) {
    if (!std::filesystem::is_directory(o.camera)) throw CommandInputError(o.camera + ": not a folder of camera views");
    camera = std::make_unique<perception::FolderCamera>(o.camera);
    images = std::make_unique<perception::ImageObjectRecognizer>(std::make_shared<perception::CocoDetector>(), nullptr, ontology);
    eyes = std::make_unique<perception::CameraObjectRecognizer>(*camera, *images);
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
  const domains::MissionRun run = domains::run_mission(input, options);
  print_mission(run);
  return run.report.goal_reached ? kExitOk : kExitInvalid;
}

}  // namespace

void add_deliberate_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<DeliberateOptions>();
  CLI::App* cmd = app.add_subcommand("deliberate", "One senior end to end: stress, emotion, goal, plan, act, monitor, repair");
  cmd->add_option("--domains-dir", o->dir, "Folder with domain.pddl, types.ttl and the problems");
  cmd->add_option("--problem", o->problem, "The home's problem file in that folder (its goal is replaced)");
  cmd->add_option("--senior", o->senior, "The senior wearing the wristband");
  cmd->add_option("--ppg", o->ppg, "The wristband's PPG (CSV time,ppg); default: the simulator's senior");
  cmd->add_option("--calm-seconds", o->calm_s, "Simulated senior: seconds calm first")->check(CLI::Range(0.0, 3600.0));
  cmd->add_option("--stressed-seconds", o->stressed_s, "Simulated senior: then seconds stressed")->check(CLI::Range(40.0, 3600.0));
  cmd->add_flag("--calm", o->calm_only, "Simulated senior: never stressed");
  cmd->add_option("--seed", o->seed, "Seed of the simulated senior");
  cmd->add_option("--stress-model", o->stress_model, "A stress model (perceive stress train/--save); default: trained on the simulator");
  cmd->add_option("--face", o->face, "An image of the senior's face (the pretrained emotion network reads it)");
  cmd->add_option("--emotion", o->emotion, "The emotion, when no face image is at hand (said to be given)");
  cmd->add_option("--looks", o->looks, "Times the robot looks at the face (the boredom rule needs repeated neutral looks)");
  cmd->add_option("--camera", o->camera, "Folder with a subfolder of images per location: what the robot's camera sees");
  cmd->add_option("--unavailable", o->unavailable, "OBJECT@TIME: the object becomes unavailable then (repeatable)");
  cmd->add_option("--strategy", o->strategy, "Repair strategy: replan, substitute, suggest, patch, adapt");
  cmd->callback([o, &exit_code] { exit_code = guarded([&] { return run(*o); }, o->problem); });
}

}  // namespace alplan::cli
