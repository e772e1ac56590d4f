// The reference semantics of a timed plan: PDDL 2.1's happenings (Fox &
// Long, JAIR 20, 2003, sections 8-9) with the conventions VAL implements
// (KCL-Planning/VAL, Validate -t E), written anew from their definitions
// and VAL's behaviour; oracle/README.md says which rule comes from where.
//
//  - Each step is a happening member at its time: an instantaneous action;
//    a durative action's start at t and its end at t + d; each timed
//    initial literal, at its time, is a member too. Members within E/10 of
//    a happening's first member join it; the happening's time is its first.
//  - In a happening, every member's conditions (duration constraints first)
//    hold in the state before it; the members do not interfere
//    (ownership.h); their effects are worked out on the state before and
//    applied together (effects.h); derived atoms are recomputed.
//  - After every happening but the last, each action running across the
//    interval that follows (started at or before it, ending after it) has
//    its over-all conditions hold in the state after it: the open interval.
//  - The goal holds in the state after the last happening, timed literals
//    included; trajectory constraints hold over the states (trajectory.h).
//  - The value is the metric in the state after the last happening at or
//    before the plan's last action ((total-time) being its time when the
//    domain declares :durative-actions or :time, the number of steps and
//    timed literals otherwise), or, with no metric, that number; unnamed
//    preferences adjust it as VAL does (README).
//
// Comparisons: VAL judges conditions with a fixed 1e-4 slack and over-all
// conditions exactly; `exact` judges everything exactly (the brute force
// and the planner's plans, which must hold without slack). Duration
// constraints are met within E either way, as VAL has it.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "oracle/action_parts.h"
#include "oracle/timed_plan.h"
#include "oracle/world.h"

namespace alplan::oracle {

struct JudgeOptions {
  double tolerance = 0.001;  // VAL's -t
  bool exact = false;        // exact comparisons instead of VAL's slack
  bool check_goal = true;    // false: judge a prefix, the goal and the end of trajectory aside
  // Also judge each pair of a happening's members by all they claim,
  // whatever VAL's order of claims (ownership.h): stricter than VAL.
  bool symmetric_mutex = false;
  // Above 0: also a mutex where two happenings at distinct times closer
  // than this touch one fact or fluent, one writing it, in a way that does
  // not commute (the symmetric rule across the gap; ownership.h). Stricter
  // than VAL, which judges distinct times apart however close: what a
  // planner that separates interfering happenings by epsilon can produce.
  double epsilon_separation = 0.0;
};

enum class Failure : unsigned char {
  None,
  BadPlan,       // an unknown action or object, a wrong argument, no duration
  Duration,      // a duration constraint fails
  Precondition,  // a condition at a start, an end or an instantaneous action
  Mutex,         // two members of one happening interfere
  Invariant,     // an over-all condition fails on an interval
  Constraint,    // a hard trajectory constraint is broken
  Goal,          // the goal does not hold at the end
  NotJudged,     // an undefined value is read, or a construct is not judged here
};
const char* to_string(Failure failure);

struct Verdict {
  Failure failure = Failure::None;
  std::string reason;
  double time = 0.0;  // of the happening where the plan failed
  double value = 0.0;
  double makespan = 0.0;
  std::map<std::string, double> preference_violations;
  bool valid() const { return failure == Failure::None; }
  bool judged() const { return failure != Failure::NotJudged; }
};

class Judge {
 public:
  Judge(std::shared_ptr<const pddl::Domain> domain, std::shared_ptr<const pddl::Problem> problem,
        JudgeOptions options = {});
  ~Judge();
  Judge(const Judge&) = delete;
  Judge& operator=(const Judge&) = delete;

  Verdict judge(const TimedPlan& plan);
  const JudgeOptions& options() const { return options_; }

 private:
  class Run;
  const ActionParts& parts(const std::string& action);

  World world_;
  JudgeOptions options_;
  std::map<std::string, ActionParts> parts_;
};

}  // namespace alplan::oracle
