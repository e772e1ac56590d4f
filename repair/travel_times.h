// Shortest travelling times over a home's map: its places joined by ways
// (`path` facts) that take the times `moving_time` gives them. One
// Dijkstra for everything that asks how far a place is: the search for a
// lost senior (person_search.h) and the home's dispatch of the nearest
// robot (home/robot_dispatch.h).
#pragma once

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace alplan::repair {

// From each place, the places one way leads to and the time it takes
// (non-negative).
using Ways = std::map<std::string, std::vector<std::pair<std::string, double>>>;

// The shortest time from any of `sources` to every place `ways` lead to
// from them (the sources at 0); places not reached are absent.
std::map<std::string, double> shortest_times(const Ways& ways, const std::set<std::string>& sources);

}  // namespace alplan::repair
