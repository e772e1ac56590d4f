// PDDL 3 (Gerevini & Long 2005, "Plan constraints and preferences in PDDL3"),
// normalised: the trajectory constraints of the domain and problem, the
// preferences of the goal, and the names `is-violated` counts. Plain data;
// action precondition preferences live in their ActionSchema. The validator
// evaluates them (trajectory_monitor.h); the planner compiles them away
// (pddl3_compilation.h) and treats preferences as costs (preference_search.h).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "planner/lifted_formula.h"

namespace alplan {

enum class ModalOperator : unsigned char {
  AtEnd,           // (at end φ): φ in the final state
  Always,          // φ in every state
  Sometime,        // φ in some state
  Within,          // (within t φ): φ in some state at time <= t
  AtMostOnce,      // φ becomes true at most once
  SometimeAfter,   // (sometime-after φ ψ): after each state with φ, ψ at it or later
  SometimeBefore,  // (sometime-before φ ψ): ψ strictly before the first state with φ
  AlwaysWithin,    // (always-within t φ ψ): after each state with φ, ψ within t
  HoldDuring,      // (hold-during t1 t2 φ): φ in every state at t1 <= time < t2
  HoldAfter,       // (hold-after t φ): φ in every state at time > t
};

const char* to_string(ModalOperator op);

// One modal formula, under the foralls that enclose it (outermost first);
// each binding of them is one instance.
struct LiftedConstraint {
  ModalOperator op = ModalOperator::Always;
  LiftedCondition requirement;  // φ, or ψ of the two-formula operators
  LiftedCondition trigger;      // φ of sometime-after, sometime-before, always-within
  double deadline = 0.0;        // within, always-within: t; hold-during: t2; hold-after: t
  double from = 0.0;            // hold-during: t1
  std::vector<QuantifiedVariable> forall;
  std::uint32_t variable_slots = 0;
  // Set for a soft constraint: index into TrajectoryConstraints::preferences.
  std::optional<std::uint32_t> preference;
  // VAL counts a violated preference once per monitor: instances that differ
  // in the first `separate` forall variables (those outside the preference)
  // have monitors of their own; variables of a forall inside the preference
  // share one, so that (preference p (forall (?x) (always φ))) counts once.
  std::size_t separate = 0;
  std::uint32_t monitor_group = 0;
  std::string text;   // the constraint as written, for messages
  std::string where;  // file:line:column
};

// A preference in the goal or an action's condition: each instance (a binding
// of `forall`, the universal quantifiers enclosing it) that fails counts one
// violation when the condition is evaluated.
struct PreferenceCondition {
  std::uint32_t preference = 0;
  std::vector<QuantifiedVariable> forall;
  LiftedCondition condition;
  pddl::TimeSpecifier time = pddl::TimeSpecifier::AtStart;  // durative actions
  std::string where;
};

struct TrajectoryConstraints {
  // Preference names (unnamed ones are "anonymous", as in VAL), in order of
  // first mention; (is-violated n) of a name never declared counts 0.
  std::vector<std::string> preferences;
  std::vector<LiftedConstraint> constraints;
  std::vector<PreferenceCondition> goal_preferences;
  // Every PDDL 3 construct met, "file:line:col: what", in the order met;
  // the planner names the first when it refuses the task.
  std::vector<std::string> uses;

  bool empty() const { return uses.empty(); }
};

}  // namespace alplan
