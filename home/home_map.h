// What a home is, read off its planning problem: the rooms and the paths
// between them (with a drawing of the map), the seniors and where they
// live, the robots, and the portable objects. Generated homes and the
// paper's home are read alike, so the home loop and the report need no
// other description.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pddl_parser/ast.h"

namespace alplan::home {

struct Room {
  std::string name, type;
  double x = 0.0, y = 0.0;  // for drawing: corridors in a row, rooms beside them
};

struct Placed {
  std::string name, type, room;
};

struct HomeMap {
  std::string name;
  std::vector<Room> rooms;
  std::vector<std::pair<std::string, std::string>> connections;  // each path once
  std::vector<Placed> seniors, robots, objects;

  // The first log line's `home` field (event_log.h).
  nlohmann::json json() const;
  bool has_senior(const std::string& name) const;
  bool has_robot(const std::string& name) const;
};

// Throws std::invalid_argument when the problem has no robot, no senior or
// no path between rooms.
HomeMap read_home_map(const pddl::Problem& problem);

}  // namespace alplan::home
