// Typed records of why a plan is invalid, in the manner of VAL's error
// records. The monitor uses the same records as its failure records.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

namespace alplan {

struct Violation {
  enum class Kind : unsigned char {
    UnsatisfiedPrecondition,  // an at-start, at-end or instantaneous condition
    UnsatisfiedInvariant,     // an over-all condition, on [time, until)
    MutexViolation,           // two interfering happenings at one time
    DurationViolation,        // the [d] of a step breaks its duration constraint
    GoalNotReached,
    UnknownAction,
    UnknownObject,
    BadStep,                  // wrong number or type of arguments, missing duration
    UndefinedValue,           // a numeric value the problem never defined
    Unsupported,              // a construct the validator cannot execute
    ConstraintViolated,       // a hard PDDL 3 trajectory constraint
  };
  Kind kind = Kind::GoalNotReached;
  double time = 0.0;
  double until = 0.0;        // UnsatisfiedInvariant: end of the interval
  std::string action;        // "(load h1 c1 t1 d0) - start"
  std::string condition;     // the violated condition, as PDDL
  std::string other_action;  // MutexViolation: the other party
  std::size_t step = std::numeric_limits<std::size_t>::max();  // index into the plan
  std::uint32_t line = 0;    // line in the plan file, when known

  // One sentence, worded like VAL's where VAL has a wording.
  std::string message() const;
};

const char* to_string(Violation::Kind kind);

}  // namespace alplan
