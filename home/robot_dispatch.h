// Which robots a mission plans with: one per senior in need, the nearest
// free one by travelling time, as a care home sends the nearest carer.
//
// Why not every robot: the planner's temporal relaxed planning graph lets a
// remedy's steps be shared between robots (one fills the glass, another
// hands it over), so a robot's real progress often leaves the heuristic
// flat, and the plateau grows with every robot that can move. The same
// one-goal task of a generated home took 43, 491, 3,542 and 15,215
// expansions with 1, 2, 3 and 4 robots (`alplan plan`, home/README.md).
// Planning with the dispatched robots keeps each mission's search to the
// robots that serve it; the others stay out of the problem (they keep
// their places in the world and serve the next mission).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "pddl_parser/ast.h"
#include "repair/travel_times.h"

namespace alplan::home {

// Travelling times over the problem's `path` facts and `moving_time`
// values (1 where a path has none), and where things are by `(be x room)`.
class TravelTimes {
 public:
  explicit TravelTimes(const pddl::Problem& problem);
  std::optional<std::string> room_of(const std::string& thing) const;
  // The shortest time from each room that can reach `room` to it.
  std::map<std::string, double> times_to(const std::string& room) const;

 private:
  repair::Ways into_;  // the ways reversed: from each room to those that lead into it
  std::map<std::string, std::string> room_of_;
};

// A senior to serve, most urgent first.
struct Call {
  std::string senior;
  double window_end = 0.0;
};

// For each call in order of urgency, the robot (not yet chosen) that
// reaches the senior's room soonest over the problem's `path` facts and
// `moving_time` values; robots are where `(be robot room)` says. With
// fewer robots than calls, each robot serves one call and the rest share
// them. Robots with no known room are not chosen; returns the names in the
// order chosen (empty when no robot has a known room).
std::vector<std::string> dispatch_robots(const pddl::Problem& problem, const std::vector<std::string>& robots,
                                         std::vector<Call> calls);

// The problem without the robots not in `keep`: their objects, and every
// initial atom, value and timed literal that names them.
pddl::Problem with_robots_only(const pddl::Problem& problem, const std::vector<std::string>& all_robots,
                               const std::vector<std::string>& keep);

}  // namespace alplan::home
