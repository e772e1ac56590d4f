// The three-part explanation of a repair the paper's Discussion asks for:
// why the plan (the goal and the emotion behind it), what went wrong (the
// violated condition, the action, the time), how it was repaired (which
// object or suggestion, and why) — or, for a repair that failed, why it
// could not be. Every repair record carries one, failed or not. As text for
// people, as JSON for tools.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "planner/violation.h"

namespace alplan::repair {

struct Explanation {
  std::string why;
  std::string what;
  std::string how;  // how it was repaired, or why it could not be
  bool repaired = true;

  std::string text() const;
  nlohmann::json json() const;
};

// "At 140.008, (available glass_id05), which (carry ...) - start needs, does
// not hold in the observed state."
std::string describe_failure(const Violation& failure, bool foreseen);

}  // namespace alplan::repair
