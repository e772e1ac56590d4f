#include "home/simulated_senior.h"

#include <algorithm>
#include <cmath>

namespace alplan::home {
namespace {

perception::Emotion shown(const Episode* episode, double coin) {
  using perception::Emotion;
  if (!episode) return coin < 0.7 ? Emotion::Neutral : Emotion::Happy;
  if (episode->emotion == "terrified") return Emotion::Terrified;
  if (episode->emotion == "sad") return Emotion::Sad;
  return Emotion::Neutral;  // bored
}

// The seven classes a FER2013 reader names (it has no "bored").
constexpr perception::Emotion kFaceClasses[] = {
    perception::Emotion::Terrified, perception::Emotion::Angry,   perception::Emotion::Disgusted,
    perception::Emotion::Happy,     perception::Emotion::Neutral, perception::Emotion::Sad,
    perception::Emotion::Surprised};

}  // namespace

SimulatedSenior::SimulatedSenior(std::string name, std::uint64_t seed, const SeniorModelOptions& options,
                                 std::vector<Episode> scripted)
    : name_(std::move(name)),
      options_(options),
      scripted_(!scripted.empty()),
      random_(seed),
      face_random_(seed ^ 0x9e3779b97f4a7c15ULL),
      pulse_(seed * 31 + 7),
      profile_(pulse_.random_subject()),
      response_(pulse_.random_stress_response()),
      episodes_(std::move(scripted)),
      // The phase from the seed, as the alarm study's: no other random stream.
      drift_phase_(6.283185307179586 * std::fmod(static_cast<double>(seed) * 0.6180339887498949, 1.0)) {}

double SimulatedSenior::uniform() { return static_cast<double>(random_() >> 11) * 0x1.0p-53; }

// Draws episodes while calm until one starts after t (or never, scripted).
void SimulatedSenior::draw_until(double t) {
  if (scripted_ || options_.episodes_per_hour <= 0.0) return;
  while (episodes_.empty() || (std::isfinite(episodes_.back().end) && episodes_.back().end <= t)) {
    const double from = episodes_.empty() ? options_.calm_start_s : episodes_.back().end;
    const double gap = -std::log(1.0 - uniform()) * 3600.0 / options_.episodes_per_hour;
    const double pick = uniform();
    const char* emotion = pick < options_.terrified_share                       ? "terrified"
                          : pick < options_.terrified_share + options_.sad_share ? "sad"
                                                                                 : "bored";
    episodes_.push_back({from + gap, emotion});
    if (episodes_.back().start > t) return;
  }
}

const Episode* SimulatedSenior::episode_at(double t) {
  draw_until(t);
  for (const Episode& e : episodes_) {
    if (e.start <= t && t < e.end) return &e;
  }
  return nullptr;
}

std::vector<perception::StressWindow> SimulatedSenior::readings_until(double t) {
  const double window = 30.0;
  while (simulated_until_ < t) {
    // A chunk with the lead-in its first windows need, so that windows
    // end every 5 s across chunks as they would on one long recording.
    const double start = simulated_until_;
    const bool stressed = episode_at(start) != nullptr;
    perception::RecordingConditions conditions;
    conditions.sample_rate_hz = options_.sample_rate_hz;
    conditions.duration_s = options_.chunk_s + window + 5.0;  // the core closes a window a hop later
    perception::SubjectProfile resting = profile_;
    resting.resting_hr_bpm +=
        options_.drift_bpm * std::sin(6.283185307179586 * (start + 0.5 * options_.chunk_s) / 1200.0 + drift_phase_);
    const perception::SubjectProfile body = stressed ? perception::under_stress(resting, response_) : resting;
    const perception::SimulatedRecording recording = pulse_.simulate(body, conditions);
    for (perception::StressWindow w : perception::stress_windows(recording.recording)) {
      if (w.end_s <= window + 1e-9 || w.end_s > window + options_.chunk_s + 1e-9) continue;
      w.end_s += start - window;
      buffered_.push_back(w);
    }
    simulated_until_ = start + options_.chunk_s;
  }
  const auto due = std::partition_point(buffered_.begin(), buffered_.end(),
                                        [t](const perception::StressWindow& w) { return w.end_s <= t; });
  std::vector<perception::StressWindow> out(buffered_.begin(), due);
  buffered_.erase(buffered_.begin(), due);
  return out;
}

perception::EmotionReading SimulatedSenior::look(double t) {
  const auto draw = [this] { return static_cast<double>(face_random_() >> 11) * 0x1.0p-53; };
  const perception::Emotion face = shown(episode_at(t), draw());
  perception::EmotionReading reading;
  if (draw() < options_.face_accuracy) {
    reading.top = face;
    reading.score = static_cast<float>(0.55 + 0.4 * draw());
  } else {
    std::vector<perception::Emotion> others;
    for (perception::Emotion e : kFaceClasses) {
      if (e != face) others.push_back(e);
    }
    reading.top = others[static_cast<std::size_t>(draw() * static_cast<double>(others.size())) % others.size()];
    reading.score = static_cast<float>(0.3 + 0.3 * draw());
  }
  return reading;
}

void SimulatedSenior::remedied(double t, const std::string& emotion) {
  draw_until(t);
  for (Episode& e : episodes_) {
    if (e.start <= t && t < e.end && e.emotion == emotion) e.end = t + options_.recovery_s;
  }
}

}  // namespace alplan::home
