#include "home/face_looks.h"

#include "domains/emotion_goals.h"

namespace alplan::home {

std::optional<PerceivedGoal> FaceLooks::look(const std::string& senior, const perception::StressState& stress, double t,
                                             const Look& read_face) {
  if (!stress.stressed) {
    // Looks are taken only while stressed: calm again is where the episode ends.
    generator_.episode_ended(senior);
    if (checking_.erase(senior)) busy_.insert(senior);  // the overdue goal stays in course
    return std::nullopt;
  }
  if (busy_.count(senior)) return std::nullopt;
  double& due = next_look_.try_emplace(senior, t).first->second;
  if (due > t) return std::nullopt;
  due = t + settings_.look_interval_s;
  const std::optional<perception::EmotionReading> reading = read_face(senior, t);
  if (!reading) return std::nullopt;
  LogEvent look{"emotion", t, senior, {}, {}};
  look.payload = {{"emotion", std::string(perception::emotion_name(reading->top))}, {"score", reading->score},
                  {"look", ++looks_[senior]}};
  log_.write(look);
  const std::optional<perception::GeneratedGoal> made = generator_.generate(senior, stress, *reading);
  if (!made) return std::nullopt;
  PerceivedGoal goal = goal_of(senior, *made, t);
  busy_.insert(senior);
  if (const auto checked = checking_.find(senior); checked != checking_.end()) {
    const std::string in_course = checked->second;
    checking_.erase(checked);
    if (in_course == goal.predicate) {  // confirmed: the goal in course stays, late
      LogEvent confirmed{"goal_confirmed", t, senior, {}, {}};
      confirmed.payload = {{"goal", "(" + goal.predicate + " " + senior + ")"}};
      log_.write(confirmed);
      return std::nullopt;
    }
    goal.supersedes = in_course;
  }
  LogEvent event{"goal", t, senior, {}, {}};
  event.payload = {{"goal", "(" + goal.predicate + " " + senior + ")"}, {"emotion", goal.emotion},
                   {"motivation", goal.motivation}, {"decided_by", goal.decided_by},
                   {"window_end", goal.window_end}};
  if (!goal.supersedes.empty()) event.payload["supersedes"] = "(" + goal.supersedes + " " + senior + ")";
  log_.write(event);
  return goal;
}

PerceivedGoal FaceLooks::goal_of(const std::string& senior, const perception::GeneratedGoal& made, double t) const {
  PerceivedGoal goal;
  goal.senior = senior;
  goal.emotion = std::string(*perception::emotion_predicate(made.emotion));
  goal.predicate = std::string(*domains::goal_for_emotion(goal.emotion));
  goal.window = goal.emotion == "terrified" ? "hydration_time" : "comfort_time";
  goal.goal = made.goal;
  goal.motivation = made.motivation;
  goal.decided_by = made.decided_by;
  goal.time = t;
  goal.window_end = t + (goal.emotion == "terrified" ? settings_.terrified_window_s : settings_.other_window_s);
  return goal;
}

void FaceLooks::comforted(const std::string& senior, double t) {
  busy_.erase(senior);
  checking_.erase(senior);
  generator_.episode_ended(senior);
  next_look_[senior] = t + settings_.grace_s;
}

void FaceLooks::missed(const std::string& senior, double t) {
  busy_.erase(senior);
  checking_.erase(senior);
  next_look_[senior] = t;
}

void FaceLooks::overdue(const PerceivedGoal& goal, double t) {
  busy_.erase(goal.senior);
  checking_[goal.senior] = goal.predicate;
  next_look_[goal.senior] = t;
}

}  // namespace alplan::home
