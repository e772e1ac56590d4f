#include "home/home_perception.h"

#include <stdexcept>

#include "domains/emotion_goals.h"
#include "perception/stress/simulated_stress_model.h"

namespace alplan::home {
namespace {

// The detector `alplan deliberate` uses: trained on the simulator's
// labelled database, not on the home's seniors.
std::unique_ptr<perception::StressDetector> make_detector(std::uint64_t seed, std::size_t follow_readings) {
  perception::SimulatedModelSpec spec;
  spec.subjects = 24;
  spec.recording_s = 150;
  spec.seed = seed + 1;
  spec.classifier = {};
  perception::StressCalibration calibration;
  calibration.follow_readings = follow_readings;
  return std::make_unique<perception::ClassifierStressDetector>(perception::train_simulated_stress_classifier(spec),
                                                                perception::StressSmoothing{}, calibration);
}

}  // namespace

HomePerception::HomePerception(const HomeMap& map, const HomeSettings& settings, EventLog& log)
    : log_(log), detector_(make_detector(settings.seed, settings.stress_follow_readings)), looks_(settings, log) {
  std::map<std::string, std::vector<Episode>> script;
  for (const ScriptedEpisode& e : settings.script) {
    if (!map.has_senior(e.senior)) throw std::invalid_argument("the script names " + e.senior + ", not a senior of the home");
    if (!domains::goal_for_emotion(e.emotion)) throw std::invalid_argument("the script's emotion " + e.emotion + " is not terrified, sad or bored");
    script[e.senior].push_back({e.start, e.emotion});
  }
  SeniorModelOptions model = settings.seniors;
  if (!settings.script.empty()) model.episodes_per_hour = 0.0;
  std::uint64_t serial = 0;
  for (const Placed& s : map.seniors) {
    ++serial;
    seniors_[s.name] = std::make_unique<SimulatedSenior>(s.name, settings.seed * 1000003 + serial, model, script[s.name]);
  }
}

HomePerception::~HomePerception() = default;

std::size_t HomePerception::episodes_begun(double until) const {
  std::size_t n = 0;
  for (const auto& [name, senior] : seniors_) {
    for (const Episode& e : senior->episodes()) n += e.start <= until;
  }
  return n;
}

void HomePerception::read_wristbands(double t) {
  for (auto& [name, senior] : seniors_) {
    for (const perception::StressWindow& w : senior->readings_until(t)) {
      const perception::StressObservation seen = detector_->observe(name, w.features);
      if (!seen.changed) continue;
      LogEvent event{"stress", w.end_s, name, {}, {}};
      event.payload = {{"stressed", seen.state.stressed}, {"score", seen.state.stressed_fraction},
                       {"votes", seen.state.votes}};
      log_.write(event);
      if (seen.state.stressed) {
        const Episode* episode = senior->episode_at(w.end_s);
        if (episode) detected_.insert({name, episode->start});
        else ++false_alarms_;
        looks_.stressed(name, w.end_s);
      }
    }
  }
}

std::vector<PerceivedGoal> HomePerception::look_at_faces(double t) {
  std::vector<PerceivedGoal> goals;
  for (auto& [name, senior] : seniors_) {
    const std::optional<perception::StressState> stress = detector_->state(name);
    if (!stress) continue;
    SimulatedSenior& seen = *senior;
    const auto read_face = [&seen](const std::string&, double when) { return std::optional(seen.look(when)); };
    if (std::optional<PerceivedGoal> goal = looks_.look(name, *stress, t, read_face)) goals.push_back(std::move(*goal));
  }
  return goals;
}

std::vector<PerceivedGoal> HomePerception::sense(double t) {
  read_wristbands(t);
  return look_at_faces(t);
}

void HomePerception::comforted(const PerceivedGoal& goal, double t) {
  seniors_.at(goal.senior)->remedied(t, goal.emotion);
  looks_.comforted(goal.senior, t);
}

void HomePerception::missed(const PerceivedGoal& goal, double t) {
  looks_.missed(goal.senior, t);
}

std::optional<PerceptionScore> HomePerception::score(double until) const {
  return PerceptionScore{episodes_begun(until), episodes_detected(), false_alarms()};
}

}  // namespace alplan::home
