// PDDL 3 trajectory constraints, hard and soft (Gerevini & Long, "Plan
// Constraints and Preferences in PDDL3", 2005, section 3), judged over the
// states a plan passes through: the initial state at time 0 and the state
// after each happening at that happening's time (and, as VAL observes them,
// once more at the next happening's time where an invariant is checked in
// between: the same state, still holding then).
//
// With S_i observed at t_i (i = 0..n), as the paper defines them:
//   always φ              every S_i satisfies φ
//   sometime φ            some S_i does
//   within t φ            some S_i with t_i <= t does
//   at-most-once φ        φ holds on at most one unbroken run of states
//   sometime-after φ ψ    every S_i with φ has ψ in some S_j, j >= i
//   sometime-before φ ψ   every S_i with φ has ψ in some S_j, j < i
//   always-within t φ ψ   every S_i with φ has ψ in some S_j, j >= i,
//                         t_j - t_i <= t
//   hold-during t1 t2 φ   every S_i with t1 <= t_i < t2 satisfies φ
//   hold-after t φ        every S_i with t_i > t satisfies φ
//   at end φ              the final state satisfies φ
// A hard constraint violated makes the plan invalid; a preference violated
// counts 1 for its instance (each instance of a forall outside the
// preference is one; a forall inside it is one), whatever the number of
// states that violate it, as VAL counts it.
//
// Two deliberate differences from VAL (documented in oracle/README.md):
// VAL checks hold-during only at its first observation inside the window,
// and reads hold-after as always from time 0; both are read here as the
// paper defines them. No shared plan uses either.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "oracle/evaluate.h"

namespace alplan::oracle {

class TrajectoryMonitor {
 public:
  // Gathers the constraints of the domain and the problem, forall expanded.
  TrajectoryMonitor(World& world, Comparisons comparisons);

  bool empty() const { return constraints_.empty(); }
  // One observation. False when a hard constraint is broken by it; the
  // reason is then set.
  bool observe(const State& state, double time);
  // The end of the trajectory: at end, and what is still owed.
  bool finish(const State& final_state);
  // Violations per preference name (anonymous ones under "anonymous").
  void add_violations(std::map<std::string, double>& counts) const;
  const std::string& reason() const { return reason_; }

 private:
  struct Formula {
    const pddl::Condition* condition = nullptr;
    Binding binding;
  };
  struct Constraint {
    pddl::Condition::Kind kind = pddl::Condition::Kind::Always;
    Formula first, second;  // the trigger and the requirement, where two
    std::vector<double> numbers;
    int preference = -1;    // index into preferences_, or -1: hard
    std::string text;       // as written, for the reason
    // The state of its check.
    bool done = false, seen = false, broken = false;
    int run = 0;            // at-most-once: 0 not yet, 1 holding, 2 over
    std::vector<double> deadlines;   // within, always-within: owed by then
    bool owed = false;               // sometime-after: a trigger not yet met
  };
  struct Preference {
    std::string name;
    bool violated = false;
  };

  void gather(const pddl::Condition& c, Binding& binding, int preference);
  bool holds(const Formula& f, const State& state);
  bool check(Constraint& c, const State& state, double time);
  bool fail(Constraint& c, const std::string& why);

  World& world_;
  Comparisons comparisons_;
  std::vector<Constraint> constraints_;
  std::vector<Preference> preferences_;
  std::string reason_;
};

}  // namespace alplan::oracle
