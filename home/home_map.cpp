#include "home/home_map.h"

#include <algorithm>
#include <deque>
#include <functional>
#include <set>
#include <stdexcept>

namespace alplan::home {
namespace {

std::map<std::string, std::string> object_types(const pddl::Problem& problem) {
  std::map<std::string, std::string> types;
  for (const pddl::TypedName& o : problem.objects) types[o.name] = o.types.empty() ? "object" : o.types.front();
  return types;
}

// A tidy tree drawing: depth across, leaves one below another in the
// order a depth-first walk meets them, a parent beside the middle of its
// children. The home's paths form a tree or nearly one; a path that closes
// a cycle is drawn but does not move anything.
void lay_out(std::vector<Room>& rooms, const std::vector<std::pair<std::string, std::string>>& connections) {
  std::map<std::string, std::vector<std::string>> next;
  for (const auto& [a, b] : connections) {
    next[a].push_back(b);
    next[b].push_back(a);
  }
  std::map<std::string, Room*> by_name;
  for (Room& r : rooms) by_name[r.name] = &r;
  std::set<std::string> placed;
  double row = 0.0;
  const std::function<double(const std::string&, int)> place = [&](const std::string& room, int depth) {
    placed.insert(room);
    std::vector<double> child_rows;
    for (const std::string& n : next[room]) {
      if (!placed.count(n)) child_rows.push_back(place(n, depth + 1));
    }
    Room& r = *by_name[room];
    r.x = depth;
    r.y = child_rows.empty() ? row++ : (child_rows.front() + child_rows.back()) / 2.0;
    return r.y;
  };
  // Start from a corridor when there is one: the home's spine.
  const auto spine = std::find_if(rooms.begin(), rooms.end(), [](const Room& r) { return r.type == "corridor"; });
  for (const Room& r : rooms) {
    const std::string& start = spine != rooms.end() && placed.empty() ? spine->name : r.name;
    if (!placed.count(start)) place(start, 0);
  }
}

}  // namespace

nlohmann::json HomeMap::json() const {
  nlohmann::json out{{"name", name}};
  out["rooms"] = nlohmann::json::array();
  for (const Room& r : rooms) out["rooms"].push_back({{"name", r.name}, {"type", r.type}, {"x", r.x}, {"y", r.y}});
  out["connections"] = nlohmann::json::array();
  for (const auto& [a, b] : connections) out["connections"].push_back({a, b});
  const auto placed = [](const std::vector<Placed>& list) {
    nlohmann::json array = nlohmann::json::array();
    for (const Placed& p : list) array.push_back({{"name", p.name}, {"type", p.type}, {"room", p.room}});
    return array;
  };
  out["seniors"] = placed(seniors);
  out["robots"] = placed(robots);
  out["objects"] = placed(objects);
  return out;
}

bool HomeMap::has_senior(const std::string& n) const {
  return std::any_of(seniors.begin(), seniors.end(), [&](const Placed& p) { return p.name == n; });
}

bool HomeMap::has_robot(const std::string& n) const {
  return std::any_of(robots.begin(), robots.end(), [&](const Placed& p) { return p.name == n; });
}

HomeMap read_home_map(const pddl::Problem& problem) {
  HomeMap map;
  map.name = problem.name;
  const std::map<std::string, std::string> types = object_types(problem);
  std::set<std::string> rooms;
  std::set<std::pair<std::string, std::string>> seen;
  std::map<std::string, std::string> place;
  for (const pddl::Atom& a : problem.init) {
    if (a.args.size() != 2) continue;
    const std::string &x = a.args[0].name, &y = a.args[1].name;
    if (a.name == "path") {
      rooms.insert(x);
      rooms.insert(y);
      if (!seen.count({y, x}) && seen.insert({x, y}).second) map.connections.emplace_back(x, y);
    } else if (a.name == "be") {
      place[x] = y;
    }
  }
  for (const pddl::TypedName& o : problem.objects) {
    if (rooms.count(o.name)) map.rooms.push_back({o.name, types.at(o.name)});
  }
  for (const auto& [thing, room] : place) {
    const std::string type = types.count(thing) ? types.at(thing) : "object";
    Placed p{thing, type, room};
    if (type == "senior") map.seniors.push_back(p);
    else if (type == "robot") map.robots.push_back(p);
    else map.objects.push_back(p);
  }
  if (map.robots.empty()) throw std::invalid_argument(problem.name + ": the home has no robot placed with (be robot room)");
  if (map.seniors.empty()) throw std::invalid_argument(problem.name + ": the home has no senior placed with (be senior room)");
  if (map.connections.empty()) throw std::invalid_argument(problem.name + ": the home has no (path room room)");
  lay_out(map.rooms, map.connections);
  return map;
}

}  // namespace alplan::home
