// A validation's state trace, as `alplan validate -v` prints it (VAL's -v
// shows the same things: each happening, its members, what it changed).
#pragma once

#include <string>
#include <vector>

#include "planner/ground_task.h"
#include "planner/validation_result.h"

namespace alplan {

// What one happening changed: facts that became true or false, numeric
// values that changed (undefined ones print as "undefined").
struct StateChange {
  std::vector<std::string> added;    // "(at truck0 depot0)", in fact order
  std::vector<std::string> deleted;
  std::vector<std::string> values;   // "(fuel truck0): 10 -> 8"
};

StateChange state_change(const GroundTask& task, const ExplicitState& before, const ExplicitState& after);

// The happening as lines of text:
//   Happening 1, time 0.001:
//     (lift hoist0 crate1 pallet0 depot0) - start
//     deletes (clear crate1)
//     adds (lifting hoist0 crate1)
//     (fuel truck0): 10 -> 8
//     violation: <message>
std::string format_happening(const GroundTask& task, const HappeningRecord& happening);

}  // namespace alplan
