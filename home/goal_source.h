// Where the running home's goals come from (layers 1 and 2 of the paper's
// Fig. 3): simulated seniors (home_perception.h) or the wristbands of the
// signal service in the same process (live_goal_source.h). The loop
// (home_run.h) asks for goals as its time goes and tells the source how
// each goal ended, so that the source knows when to look at the senior
// again.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"

namespace alplan::home {

struct PerceivedGoal {
  std::string senior;
  std::string emotion;    // the domain's predicate: terrified, sad, bored
  std::string predicate;  // soothed, cheerful, entertained
  std::string window;     // hydration_time, comfort_time
  pddl::Condition goal;
  std::string motivation, decided_by;
  double time = 0.0, window_end = 0.0;
  // HomeSettings::score_meetable: one idle robot could have met the window.
  bool meetable_alone = false;
  // With soft windows: the window passed and the goal is still served (late).
  bool overdue = false;
  // With soft windows: no robot has a plan that meets the window, so it is
  // planned with the window as a preference, to be served late.
  bool serve_late = false;
  // A look at window's end read another emotion: this goal replaces the
  // one in course for the senior, whose goal predicate this is.
  std::string supersedes;
  // The device of the senior's room that answers the emotion at once
  // (HomeSettings::devices), asked for in the goal; empty: none.
  std::string device;
};

// Perception scored against a simulation's truth, which only a simulated
// source has.
struct PerceptionScore {
  std::size_t episodes = 0, detected = 0, false_alarms = 0;
};

class GoalSource {
 public:
  virtual ~GoalSource() = default;
  // Senses up to the run's time t; returns the goals generated on the way,
  // logged.
  virtual std::vector<PerceivedGoal> sense(double t) = 0;
  // The senior's goal was reached at t.
  virtual void comforted(const PerceivedGoal& goal, double t) = 0;
  // The window closed first: the senior is looked at again.
  virtual void missed(const PerceivedGoal& goal, double t) = 0;
  // The window passed with the goal still in course (soft windows): the
  // senior is looked at again at once. A reading that calls for the same
  // goal confirms it (no new goal); one that calls for another makes a goal
  // that supersedes it (PerceivedGoal::supersedes).
  virtual void overdue(const PerceivedGoal& goal, double t) = 0;
  // Episodes begun by `until`, detected, and false alarms; nothing when the
  // source knows no truth to score against.
  virtual std::optional<PerceptionScore> score(double until) const = 0;
};

}  // namespace alplan::home
