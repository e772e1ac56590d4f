// The home's layers 1 and 2 over time (the paper's Fig. 3) for simulated
// seniors: every senior's wristband windows go to one stress detector;
// while a senior is stressed and has no goal in course, the home's camera
// reads their face (face_looks.h: every `look_interval_s`, one goal
// generator for the run, windows by urgency).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "home/event_log.h"
#include "home/face_looks.h"
#include "home/goal_source.h"
#include "home/home_map.h"
#include "home/home_settings.h"
#include "home/simulated_senior.h"
#include "perception/stress/stress_detector.h"

namespace alplan::home {

class HomePerception final : public GoalSource {
 public:
  // Throws std::invalid_argument for a scripted senior the home lacks.
  HomePerception(const HomeMap& map, const HomeSettings& settings, EventLog& log);
  ~HomePerception();

  // Senses up to t and returns the goals generated on the way, logged.
  std::vector<PerceivedGoal> sense(double t) override;
  // The senior's goal was reached at t: the remedy reaches the senior, and
  // the camera leaves them be for the grace period.
  void comforted(const PerceivedGoal& goal, double t) override;
  // The window closed first: the senior is looked at again at once.
  void missed(const PerceivedGoal& goal, double t) override;
  void overdue(const PerceivedGoal& goal, double t) override { looks_.overdue(goal, t); }
  std::optional<PerceptionScore> score(double until) const override;

  // Scoring against the simulation's truth (never read by the deliberation):
  // stress events raised when the senior was in no episode.
  std::size_t false_alarms() const { return false_alarms_; }
  std::size_t episodes_begun(double until) const;
  // Episodes during which the detector raised a stress event.
  std::size_t episodes_detected() const { return detected_.size(); }

 private:
  void read_wristbands(double t);
  std::vector<PerceivedGoal> look_at_faces(double t);

  EventLog& log_;
  std::map<std::string, std::unique_ptr<SimulatedSenior>> seniors_;
  std::unique_ptr<perception::StressDetector> detector_;
  FaceLooks looks_;
  std::size_t false_alarms_ = 0;
  std::set<std::pair<std::string, double>> detected_;  // senior, episode start
};

}  // namespace alplan::home
