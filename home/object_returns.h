// What the home's staff do that no robot does: an object someone took away
// (a failure of the repair study's kinds makes it unavailable) is back in
// service after a while, and a remedy handed to a senior is collected,
// emptied and put back where it belongs. Without them a home that runs for
// hours runs out of remedies: in the first eight-hour run of the 40-senior
// home, 66 of its 85 drinking vessels were gone by the fifth hour (a
// failure takes every vessel of a kitchen at once, as in the paper's
// Scenarios 1 and 2) and most goals then had no plan at all.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "repair/world_simulator.h"
#include "repair/world_state.h"

namespace alplan::home {

class ObjectReturns {
 public:
  // `home`: the problem whose :init says where each object belongs.
  ObjectReturns(const pddl::Problem& home, double return_s);

  // For each object `failure` makes unavailable: available again
  // `return_s` after it went.
  std::vector<repair::ExogenousEvent> after_failure(const std::vector<repair::ExogenousEvent>& failure) const;

  // For each object `world` shows given to `senior` (comforted, or their
  // window missed) and not already on its way back: at `t + return_s` it
  // is no longer the senior's, empty, available, and back in the room it
  // belongs in (objects the home never placed stay where they are).
  std::vector<repair::ExogenousEvent> collect_from(const repair::WorldState& world, const std::string& senior, double t);

 private:
  std::map<std::string, std::string> room_of_;
  double return_s_;
  // Each handed-over object's collection time: one already due later is
  // not scheduled twice (it could come back while given to someone else).
  std::map<repair::AtomKey, double> collecting_;
};

}  // namespace alplan::home
