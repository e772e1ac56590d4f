// Goals from the wristbands (`alplan home --live`): the signal service in
// the same process detects stress per senior and pushes its events onto
// its queue (perception/service/stress_event_queue.h, thread-safe: the
// service's request threads push, the home's loop pops); this source takes
// them at every step of the run's clock, logs them, and hands the stressed
// seniors to face_looks.h, which reads their faces (given_face.h: there is
// no camera) and makes goals with windows as the simulated home does.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "home/event_log.h"
#include "home/face_looks.h"
#include "home/goal_source.h"
#include "home/home_map.h"
#include "home/home_settings.h"
#include "perception/service/stress_event_queue.h"
#include "perception/stress/stress_detector.h"

namespace alplan::home {

class LiveGoalSource final : public GoalSource {
 public:
  // `wristband_seniors`: the seniors the wristbands belong to (the tokens
  // file's); throws std::invalid_argument naming one the home lacks, since
  // its stress could never become a goal the robots can plan for.
  LiveGoalSource(perception::service::StressEventQueue& events, FaceLooks::Look read_face, const HomeMap& map,
                 const std::vector<std::string>& wristband_seniors, const HomeSettings& settings, EventLog& log);

  // Takes every stress event queued so far (logged at t, the run's time
  // when the home heard it), then looks at the stressed seniors.
  std::vector<PerceivedGoal> sense(double t) override;
  void comforted(const PerceivedGoal& goal, double t) override { looks_.comforted(goal.senior, t); }
  void missed(const PerceivedGoal& goal, double t) override { looks_.missed(goal.senior, t); }
  void overdue(const PerceivedGoal& goal, double t) override { looks_.overdue(goal, t); }
  // Wristbands know no truth to score against.
  std::optional<PerceptionScore> score(double) const override { return std::nullopt; }

 private:
  void hear(const perception::service::StressEvent& e, double t);

  perception::service::StressEventQueue& events_;
  FaceLooks::Look read_face_;
  EventLog& log_;
  FaceLooks looks_;
  std::map<std::string, perception::StressState> stress_;  // the latest decision per senior
};

}  // namespace alplan::home
