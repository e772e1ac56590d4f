// What the home's staff do that no robot does: an object someone took away
// (a failure of the repair study's kinds makes it unavailable) is back in
// service after a while, and a remedy handed to a senior is collected,
// emptied and put back where it belongs. Without them a home that runs for
// hours runs out of remedies: in the first eight-hour run of the 40-senior
// home, 66 of its 85 drinking vessels were gone by the fifth hour (a
// failure takes every vessel of a kitchen at once, as in the paper's
// Scenarios 1 and 2) and most goals then had no plan at all.
#pragma once

#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "repair/world_simulator.h"
#include "repair/world_state.h"

namespace alplan::home {

// For each object `failure` makes unavailable: available again
// `return_s` after it went.
std::vector<repair::ExogenousEvent> returns_after_failure(const std::vector<repair::ExogenousEvent>& failure,
                                                          double return_s);

// For each object `world` shows given to `senior`: at `t + return_s` it is
// no longer the senior's, empty, available, and back in the room the home's
// problem `home` first placed it in (objects the home never placed stay).
std::vector<repair::ExogenousEvent> returns_after_comfort(const repair::WorldState& world, const pddl::Problem& home,
                                                          const std::string& senior, double t, double return_s);

}  // namespace alplan::home
