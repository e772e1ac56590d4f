#include "home/deliberator.h"

#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <thread>

#include "home/deliberation.h"
#include "perception/vision/coco_detector.h"

namespace alplan::home {

Deliberator::Deliberator(DeliberatorSettings settings)
    : settings_(std::move(settings)), home_(domains::load_home(settings_.dir, settings_.problem)),
      face_(settings_.face, settings_.emotion) {
  if (!settings_.camera.empty()) {
    if (!std::filesystem::is_directory(settings_.camera)) {
      throw std::invalid_argument(settings_.camera + ": not a folder of camera views");
    }
    images_ = std::make_unique<perception::ImageObjectRecognizer>(std::make_shared<perception::CocoDetector>(), nullptr,
                                                                  home_.ontology);
  }
}

Deliberator::~Deliberator() = default;

void Deliberator::wait(double seconds) const {
  if (seconds <= 0.0) return;
  if (settings_.wait) {
    settings_.wait(seconds);
  } else {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  }
}

std::optional<perception::EmotionReading> Deliberator::look(std::vector<std::string>& notes) {
  std::string note;
  std::optional<perception::EmotionReading> reading = face_.look(note);
  notes.push_back(std::move(note));
  return reading;
}

domains::MissionInput Deliberator::mission_input(const std::string& senior, const perception::GeneratedGoal& goal) {
  domains::MissionInput input;
  input.domain = &home_.domain;
  input.problem = reformulate_for_goal(*home_.files.problem, goal, 0.0);
  input.events = settings_.events;
  input.motivation = goal.motivation;
  input.seniors = {senior};
  input.ontology = &home_.ontology;
  eyes_.reset();
  camera_.reset();
  if (!images_) return input;
  camera_ = std::make_unique<perception::FolderCamera>(settings_.camera);
  eyes_ = std::make_unique<perception::CameraObjectRecognizer>(*camera_, *images_);
  input.recognizer = eyes_.get();
  // What the views show is really there: the simulated world gets those
  // objects from the start (no IoT sensor reports them, so the planner
  // knows them only once the camera is asked). The recogniser remembers
  // the names it gives, so the monitor's look later names them alike.
  const repair::WorldState before = repair::initial_world(input.problem);
  for (const auto& entry : std::filesystem::directory_iterator(settings_.camera)) {
    if (!entry.is_directory()) continue;
    for (const repair::RecognizedObject& seen : eyes_->recognize(before, entry.path().filename().string())) {
      input.events.push_back(repair::object_appears(0.0, seen));
    }
  }
  return input;
}

Deliberation Deliberator::on_stress(const std::string& senior, const perception::StressState& stress) {
  Deliberation out;
  // Layer 2: a look at the face, then, while no goal is decided, another
  // after the look interval (the boredom rule wants neutral faces at
  // several looks, at different times); a given emotion is one reading.
  const int looks = settings_.emotion.empty() ? std::max(1, settings_.looks) : 1;
  for (int look = 0; look < looks && !out.goal; ++look) {
    if (look > 0) wait(settings_.look_interval_s);
    out.emotion = this->look(out.notes);
    if (!out.emotion) return out;
    out.goal = generator_.generate(senior, stress, *out.emotion);
  }
  if (!out.goal) {
    const std::size_t streak = generator_.neutral_streak(senior);
    if (streak > 0) {
      out.notes.push_back("[goal] the boredom rule wants " + std::to_string(generator_.options().bored_after_neutral) +
                          " neutral looks in a row at different times; " + std::to_string(streak) +
                          " so far in this episode");
    }
    return out;
  }
  domains::ScenarioOptions options;
  options.assisted_living_dir = settings_.dir;
  options.strategy = settings_.strategy;
  try {
    out.run = domains::run_mission(mission_input(senior, *out.goal), options);
  } catch (const domains::NoInitialPlan& e) {
    out.no_plan = e.what();
  }
  return out;
}

}  // namespace alplan::home
