// A senior of the simulated home, as the world has them and as the robot's
// senses reach them: stress episodes (each with the emotion beneath it)
// arriving at random, a wristband whose pulse follows the episode, and a
// face the home's camera reads with a stated error rate.
//
// The observation model, what the deliberation can and cannot know:
// - the wristband: the PPG simulator's pulse (perception/stress/ppg_simulator.h)
//   of this senior's own profile, stressed during an episode, cut into the
//   wristband core's 30 s windows every 5 s; the stress detector sees only
//   those windows. The pulse is simulated a minute at a time, so the body
//   follows the episode to the minute, and the resting rate drifts slowly.
// - the face: an episode shows its emotion (terrified -> fear, sad -> sad,
//   bored -> a neutral face: boredom has no face of its own, which is why
//   the boredom rule exists), a calm senior a neutral or happy face; the
//   reader names the shown expression with probability `face_accuracy`,
//   else another of the seven FER2013 classes, uniformly.
// - the remedy: an episode ends (after `recovery_s`) only when the robot's
//   remedy answers the emotion beneath it; comforting a sad senior as if
//   terrified leaves them stressed, and the home sees it again.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "perception/goals/goal_generator.h"
#include "perception/stress/ppg_simulator.h"
#include "perception/stress/stress_features.h"

namespace alplan::home {

struct Episode {
  double start = 0.0;
  std::string emotion;  // terrified, sad, bored
  double end = std::numeric_limits<double>::infinity();  // until remedied
};

struct SeniorModelOptions {
  double episodes_per_hour = 0.25;  // while calm: a Poisson process
  double calm_start_s = 300.0;      // no episode before (the wristband's first minutes)
  double face_accuracy = 0.8;
  double recovery_s = 120.0;
  double chunk_s = 60.0;
  double sample_rate_hz = 50.0;
  // A resting heart rate is not a constant (posture, activity, meals): it
  // swings by up to this many bpm over a 20-minute period, the alarm
  // study's drift (perception/stress/stress_alarm_study.h), so that a
  // baseline learned in the first minutes goes stale as a real one would.
  double drift_bpm = 8.0;
  // Shares of the emotions beneath an episode: terrified, sad, bored.
  double terrified_share = 0.25, sad_share = 0.4;
};

class SimulatedSenior {
 public:
  // `scripted`: episodes that happen as given (the default home's); with
  // none, episodes are drawn.
  SimulatedSenior(std::string name, std::uint64_t seed, const SeniorModelOptions& options,
                  std::vector<Episode> scripted = {});

  const std::string& name() const { return name_; }
  // The wristband's windows ending in (last call's t, t], in order.
  std::vector<perception::StressWindow> readings_until(double t);
  // What the camera's face reader says now.
  perception::EmotionReading look(double t);
  // The robot's remedy for `emotion` reached the senior at t.
  void remedied(double t, const std::string& emotion);
  // The episode in course at t, if any (the simulation's truth, for
  // scoring only: the deliberation never reads it).
  const Episode* episode_at(double t);
  const std::vector<Episode>& episodes() const { return episodes_; }

 private:
  double uniform();
  void draw_until(double t);

  std::string name_;
  SeniorModelOptions options_;
  bool scripted_ = false;
  std::mt19937_64 random_;           // episodes
  std::mt19937_64 face_random_;      // the face reader
  perception::PpgSimulator pulse_;
  perception::SubjectProfile profile_;
  perception::StressResponse response_;
  std::vector<Episode> episodes_;
  double simulated_until_ = 0.0;  // of the pulse
  std::vector<perception::StressWindow> buffered_;
  double drift_phase_ = 0.0;
};

}  // namespace alplan::home
