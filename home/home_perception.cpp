#include "home/home_perception.h"

#include <stdexcept>

#include "domains/emotion_goals.h"
#include "perception/common/emotion.h"
#include "perception/stress/simulated_stress_model.h"

namespace alplan::home {
namespace {

// The detector `alplan deliberate` uses: trained on the simulator's
// labelled database, not on the home's seniors.
std::unique_ptr<perception::StressDetector> make_detector(std::uint64_t seed) {
  perception::SimulatedModelSpec spec;
  spec.subjects = 24;
  spec.recording_s = 150;
  spec.seed = seed + 1;
  spec.classifier = {};
  return std::make_unique<perception::ClassifierStressDetector>(perception::train_simulated_stress_classifier(spec),
                                                                perception::StressSmoothing{});
}

}  // namespace

HomePerception::HomePerception(const HomeMap& map, const HomeSettings& settings, EventLog& log)
    : settings_(settings), log_(log), detector_(make_detector(settings.seed)) {
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
        next_look_.emplace(name, w.end_s);
      }
    }
  }
}

std::vector<PerceivedGoal> HomePerception::look_at_faces(double t) {
  std::vector<PerceivedGoal> goals;
  for (auto& [name, senior] : seniors_) {
    const std::optional<perception::StressState> stress = detector_->state(name);
    if (!stress || !stress->stressed || busy_.count(name)) continue;
    double& due = next_look_.try_emplace(name, t).first->second;
    if (due > t) continue;
    due = t + settings_.look_interval_s;
    const perception::EmotionReading reading = senior->look(t);
    LogEvent look{"emotion", t, name, {}, {}};
    look.payload = {{"emotion", std::string(perception::emotion_name(reading.top))}, {"score", reading.score},
                    {"look", ++looks_[name]}};
    log_.write(look);
    const std::optional<perception::GeneratedGoal> made = generator_.generate(name, *stress, reading);
    if (!made) continue;
    PerceivedGoal goal;
    goal.senior = name;
    goal.emotion = std::string(*perception::emotion_predicate(made->emotion));
    goal.predicate = std::string(*domains::goal_for_emotion(goal.emotion));
    goal.window = goal.emotion == "terrified" ? "hydration_time" : "comfort_time";
    goal.goal = made->goal;
    goal.motivation = made->motivation;
    goal.decided_by = made->decided_by;
    goal.time = t;
    goal.window_end = t + (goal.emotion == "terrified" ? settings_.terrified_window_s : settings_.other_window_s);
    busy_.insert(name);
    LogEvent event{"goal", t, name, {}, {}};
    event.payload = {{"goal", "(" + goal.predicate + " " + name + ")"}, {"emotion", goal.emotion},
                     {"motivation", goal.motivation}, {"decided_by", goal.decided_by},
                     {"window_end", goal.window_end}};
    log_.write(event);
    goals.push_back(std::move(goal));
  }
  return goals;
}

std::vector<PerceivedGoal> HomePerception::sense(double t) {
  read_wristbands(t);
  return look_at_faces(t);
}

void HomePerception::comforted(const PerceivedGoal& goal, double t) {
  seniors_.at(goal.senior)->remedied(t, goal.emotion);
  busy_.erase(goal.senior);
  next_look_[goal.senior] = t + settings_.grace_s;
}

void HomePerception::missed(const PerceivedGoal& goal, double t) {
  busy_.erase(goal.senior);
  next_look_[goal.senior] = t;
}

}  // namespace alplan::home
