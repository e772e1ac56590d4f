// Layer 2 over time, whatever raised the stress: while a senior is
// stressed and has no goal in course, their face is read every
// `look_interval_s`; one goal generator, kept for the run, turns the
// readings into goals (so the boredom rule counts real looks taken at
// different times), and each goal gets its comfort window by urgency.
// Every look and goal is written to the log. Shared by the simulated
// seniors (home_perception.h) and the live wristbands (live_goal_source.h),
// which differ only in how stress is sensed and how a face is read.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "home/event_log.h"
#include "home/goal_source.h"
#include "home/home_settings.h"
#include "perception/common/emotion.h"
#include "perception/goals/goal_generator.h"
#include "perception/stress/stress_detector.h"

namespace alplan::home {

class FaceLooks {
 public:
  // Reads the senior's face at t; nothing when no face was seen.
  using Look = std::function<std::optional<perception::EmotionReading>(const std::string& senior, double t)>;

  FaceLooks(const HomeSettings& settings, EventLog& log) : settings_(settings), log_(log) {}

  // The senior became stressed at t: the first look is due then, unless one
  // is due already.
  void stressed(const std::string& senior, double t) { next_look_.emplace(senior, t); }
  // A look at a stressed senior when one is due and no goal of theirs is in
  // course; the goal it led to, logged.
  std::optional<PerceivedGoal> look(const std::string& senior, const perception::StressState& stress, double t,
                                    const Look& read_face);
  // The goal was reached: the camera leaves the senior be for the grace
  // period (the body calms down, the detector sees it later).
  void comforted(const std::string& senior, double t);
  // The window closed first: looked at again at once.
  void missed(const std::string& senior, double t);
  // The window passed with the goal in course: looked at again at once, to
  // confirm the goal or supersede it (GoalSource::overdue).
  void overdue(const PerceivedGoal& goal, double t);

 private:
  PerceivedGoal goal_of(const std::string& senior, const perception::GeneratedGoal& made, double t) const;

  const HomeSettings& settings_;
  EventLog& log_;
  perception::EmotionGoalGenerator generator_;
  std::map<std::string, double> next_look_;
  std::map<std::string, int> looks_;
  std::set<std::string> busy_;
  std::map<std::string, std::string> checking_;  // senior -> predicate of the overdue goal a look checks
};

}  // namespace alplan::home
