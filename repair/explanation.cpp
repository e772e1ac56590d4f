#include "repair/explanation.h"

#include <cstdio>

namespace alplan::repair {
namespace {

std::string time_text(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", t);
  return buffer;
}

}  // namespace

std::string Explanation::text() const {
  return "Why: " + why + "\nWhat went wrong: " + what + (repaired ? "\nHow it was repaired: " : "\nWhy it could not be repaired: ") +
         how + "\n";
}

nlohmann::json Explanation::json() const {
  return {{"why", why}, {"what", what}, {"how", how}, {"repaired", repaired}};
}

std::string describe_failure(const Violation& failure, bool foreseen) {
  using K = Violation::Kind;
  std::string out = "at " + time_text(failure.time) + ", ";
  switch (failure.kind) {
    case K::GoalNotReached:
      out += "the goal " + failure.condition + " did not hold";
      break;
    case K::UnsatisfiedInvariant:
      out += failure.condition + ", which " + failure.action + " needs throughout, did not hold";
      break;
    default:
      out += failure.condition + ", which " + failure.action + " needs, did not hold";
      break;
  }
  out += " in the observed state";
  if (foreseen) out += " (seen ahead of time: no step of the plan would have made it hold)";
  return out;
}

}  // namespace alplan::repair
