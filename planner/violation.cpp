#include "planner/violation.h"

#include "pddl_parser/writer.h"

namespace alplan {

const char* to_string(Violation::Kind kind) {
  using K = Violation::Kind;
  switch (kind) {
    case K::UnsatisfiedPrecondition: return "unsatisfied_precondition";
    case K::UnsatisfiedInvariant: return "unsatisfied_invariant";
    case K::MutexViolation: return "mutex_violation";
    case K::DurationViolation: return "duration_violation";
    case K::GoalNotReached: return "goal_not_reached";
    case K::UnknownAction: return "unknown_action";
    case K::UnknownObject: return "unknown_object";
    case K::BadStep: return "bad_step";
    case K::UndefinedValue: return "undefined_value";
    case K::Unsupported: return "unsupported";
    case K::ConstraintViolated: return "constraint_violated";
  }
  return "?";
}

std::string Violation::message() const {
  using K = Kind;
  const std::string at = pddl::format_number(time);
  const std::string in_line = line ? " (plan line " + std::to_string(line) + ")" : "";
  switch (kind) {
    case K::UnsatisfiedPrecondition:
      return action + " has an unsatisfied precondition at time " + at + ": " + condition + in_line;
    case K::UnsatisfiedInvariant:
      return "Invariant for " + action + " has its condition unsatisfied between time " + at + " to " +
             pddl::format_number(until) + ": " + condition + in_line;
    case K::MutexViolation:
      return "Mutex violation at time " + at + ": " + action + " (" + condition + ") and " + other_action;
    case K::DurationViolation:
      return "Failed duration constraint in " + action + ": " + condition + in_line;
    case K::GoalNotReached: return "The goal is not satisfied: " + condition;
    case K::UnknownAction: return "Bad plan description: unknown action " + action + in_line;
    case K::UnknownObject: return "Bad plan description: unknown object " + condition + " in " + action + in_line;
    case K::BadStep: return "Bad plan description: " + condition + " in " + action + in_line;
    case K::UndefinedValue:
      return "Attempt to access undefined expression in " + action + " at time " + at + ": " + condition + in_line;
    case K::Unsupported: return "Cannot validate: " + condition;
    case K::ConstraintViolated: return "Trajectory constraint violated at time " + at + ": " + condition;
  }
  return "?";
}

}  // namespace alplan
