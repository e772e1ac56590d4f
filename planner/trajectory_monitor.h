// Evaluates PDDL 3 trajectory constraints over the states of a plan, with
// VAL's semantics (TrajectoryConstraintsMonitor, read from its source): the
// validator shows it the initial state and the state after each happening,
// each once, at that happening's time, and the final state through
// `finish`. Times are absolute, so `within t` and `always-within t` count from
// the plan's start.
//
// Per state, in VAL's order: always; always-within triggers (a deadline
// state time + t each time its trigger holds); deadlines (passed: violated;
// met when the requirement holds at a time <= the deadline); sometime-after
// triggers (an obligation met in this state or later); sometime;
// at-most-once (true, then false, then true again is a violation);
// hold-during (t1 <= time < t2); sometime-before (the trigger holding before
// any earlier state held the requirement is a violation). hold-after t
// requires the condition in every state with time > t (Gerevini & Long; VAL
// mishandles it: its parser stores t as the start, and its monitor falls
// through into `after`). At the end: at end, and every obligation and
// deadline still open is violated.
//
// A violated hard constraint is returned as a Violation. A violated
// preference counts one violation for its monitor, at most once: VAL's
// instances of a forall outside the preference are monitored apart, those
// of a forall inside share one monitor.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "planner/explicit_state.h"
#include "planner/ground_task.h"
#include "planner/violation.h"

namespace alplan {

class TrajectoryMonitor {
 public:
  TrajectoryMonitor(const GroundTask& task, double numeric_slack);

  bool active() const { return !task_.pddl3.constraints.empty(); }
  // The first violated hard constraint, if any, in the state at `time`.
  std::optional<Violation> observe(const ExplicitState& state, double time);
  // The final state: observed, then at-end constraints and open obligations.
  std::optional<Violation> finish(const ExplicitState& state, double time);

  // One violated instance of preference `p` (a goal or precondition preference).
  void count(std::uint32_t preference) { ++violations_.at(preference); }
  // Violations per preference, indexed as TrajectoryConstraints::preferences.
  const std::vector<double>& violations() const { return violations_; }

  // What the states seen so far settle about constraint k (an index into
  // GroundTrajectory::constraints), for planning on from the last of them
  // (PreferenceSearch): a sometime or within already met, any constraint
  // already violated, an always-within deadline still open.
  bool met(std::size_t k) const { return memory_[k].met && !memory_[k].violated; }
  bool broken(std::size_t k) const { return memory_[k].violated; }
  bool deadline_open(std::size_t k) const { return !memory_[k].deadlines.empty(); }

 private:
  enum class Phase : unsigned char { NotYet, Holding, Released };
  // What one constraint instance remembers between states.
  struct Memory {
    bool met = false;                // sometime, within, a sometime-after obligation
    bool pending = false;            // sometime-after: an obligation is open
    bool requirement_seen = false;   // sometime-before
    Phase phase = Phase::NotYet;     // at-most-once
    std::vector<double> deadlines;   // always-within: open deadlines
    bool violated = false;           // at least once, hard or soft
  };

  bool holds(const ConditionSet& c, const ExplicitState& state) const;
  std::optional<Violation> check(std::size_t k, const ExplicitState& state, double time);
  std::optional<Violation> check_final(std::size_t k, const ExplicitState& state);
  // A violation of constraint k: hard ones are returned, soft ones counted.
  std::optional<Violation> violated(std::size_t k, double time, const std::string& why);

  const GroundTask& task_;
  double numeric_slack_;
  std::vector<Memory> memory_;
  std::vector<bool> monitor_counted_;
  std::vector<double> violations_;
};

}  // namespace alplan
