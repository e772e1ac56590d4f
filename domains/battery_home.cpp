#include "domains/battery_home.h"

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "repair/world_state.h"

namespace alplan::domains {
namespace {

using Graph = std::map<std::string, std::map<std::string, double>>;

// Locations joined by (path a b) with their (moving_time a b).
Graph paths_of(const pddl::Problem& problem) {
  std::map<std::pair<std::string, std::string>, double> times;
  for (const pddl::NumericFact& f : problem.numeric_init) {
    if (f.function.name == "moving_time" && f.function.args.size() == 2) {
      times[{f.function.args[0].name, f.function.args[1].name}] = f.value;
    }
  }
  Graph graph;
  for (const pddl::Atom& a : problem.init) {
    if (a.name != "path" || a.args.size() != 2) continue;
    const auto t = times.find({a.args[0].name, a.args[1].name});
    graph[a.args[0].name][a.args[1].name] = t == times.end() ? 1.0 : t->second;
    graph[a.args[1].name];  // a dead end is a location too
  }
  return graph;
}

// Shortest moving time from the nearest of `sources` to each location it
// reaches (Dijkstra; the homes are small).
std::map<std::string, double> distances_from(const Graph& graph, const std::vector<std::string>& sources) {
  std::map<std::string, double> best;
  std::set<std::pair<double, std::string>> queue;
  for (const std::string& s : sources) {
    best[s] = 0.0;
    queue.insert({0.0, s});
  }
  while (!queue.empty()) {
    const auto [d, at] = *queue.begin();
    queue.erase(queue.begin());
    const auto next = graph.find(at);
    if (next == graph.end()) continue;
    for (const auto& [to, t] : next->second) {
      const auto known = best.find(to);
      if (known != best.end() && known->second <= d + t) continue;
      if (known != best.end()) queue.erase({known->second, to});
      best[to] = d + t;
      queue.insert({d + t, to});
    }
  }
  return best;
}

// Total shortest moving time from `from` to every location; infinite when
// some location cannot be reached.
double total_time_from(const Graph& graph, const std::string& from) {
  const std::map<std::string, double> best = distances_from(graph, {from});
  if (best.size() < graph.size()) return std::numeric_limits<double>::infinity();
  double total = 0.0;
  for (const auto& [at, d] : best) total += d;
  return total;
}

// A robot's value of a one-argument function in the problem's init.
std::optional<double> find_value(const pddl::Problem& problem, const std::string& function, const std::string& robot) {
  for (const pddl::NumericFact& f : problem.numeric_init) {
    if (f.function.name == function && f.function.args.size() == 1 && f.function.args[0].name == robot) return f.value;
  }
  return std::nullopt;
}

double robot_value(const pddl::Problem& problem, const std::string& function, const std::string& robot) {
  if (const std::optional<double> v = find_value(problem, function, robot)) return *v;
  throw std::invalid_argument("battery: the home gives no (" + function + " " + robot + ")");
}

}  // namespace

nlohmann::json BatteryOptions::json() const {
  return {{"capacity", capacity}, {"reserve", reserve}, {"drain_rate", drain_rate},
          {"charge_rate", charge_rate}, {"initial", initial}};
}

BatteryOptions BatteryOptions::from_json(const nlohmann::json& j) {
  BatteryOptions o;
  try {
    o.capacity = j.at("capacity").get<double>();
    o.reserve = j.at("reserve").get<double>();
    o.drain_rate = j.at("drain_rate").get<double>();
    o.charge_rate = j.at("charge_rate").get<double>();
    o.initial = j.at("initial").get<double>();
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("battery: ") + e.what());
  }
  return o;
}

void BatteryOptions::check() const {
  if (!(drain_rate > 0.0) || !(charge_rate > 0.0)) {
    throw std::invalid_argument("battery: the drain and charge rates must be positive");
  }
  if (!(capacity > 0.0) || !(reserve >= 0.0) || reserve > capacity) {
    throw std::invalid_argument("battery: the reserve must be within 0..capacity, and the capacity positive");
  }
  if (!(initial >= 0.0) || initial > capacity) {
    throw std::invalid_argument("battery: the initial level must be within 0..capacity");
  }
}

std::string central_location(const pddl::Problem& problem) {
  const Graph graph = paths_of(problem);
  std::string best;
  double best_total = std::numeric_limits<double>::infinity();
  for (const auto& [location, next] : graph) {  // by name: the first of equals wins
    const double total = total_time_from(graph, location);
    if (best.empty() || total < best_total) {
      best = location;
      best_total = total;
    }
  }
  return best;
}

void add_batteries(pddl::Problem& problem, const BatteryOptions& options) {
  options.check();
  const std::pair<const char*, double> values[] = {
      {"battery", options.initial},        {"capacity", options.capacity},       {"reserve", options.reserve},
      {"drain_rate", options.drain_rate},  {"charge_rate", options.charge_rate}};
  for (const pddl::TypedName& o : problem.objects) {
    if (std::find(o.types.begin(), o.types.end(), "robot") == o.types.end()) continue;
    for (const auto& [function, value] : values) {
      if (find_value(problem, function, o.name)) continue;
      pddl::NumericFact f;
      f.function = repair::atom_of({function, o.name});
      f.value = value;
      problem.numeric_init.push_back(f);
    }
  }
  const bool docked = std::any_of(problem.init.begin(), problem.init.end(),
                                  [](const pddl::Atom& a) { return a.name == "dock"; });
  if (docked) return;
  const std::string dock = central_location(problem);
  if (dock.empty()) throw std::invalid_argument("battery: the home has no paths, so no place for a dock");
  problem.init.push_back(repair::atom_of({"dock", dock}));
}

std::map<std::string, double> return_levels(const pddl::Problem& problem) {
  const Graph graph = paths_of(problem);
  std::vector<std::string> docks;
  for (const pddl::Atom& a : problem.init) {
    if (a.name == "dock" && a.args.size() == 1) docks.push_back(a.args[0].name);
  }
  const std::map<std::string, double> to_dock = distances_from(graph, docks);
  double farthest = 0.0;
  for (const auto& [location, next] : graph) {
    const auto d = to_dock.find(location);
    // A location no dock can be reached from: no level brings a robot home.
    farthest = std::max(farthest, d == to_dock.end() ? std::numeric_limits<double>::infinity() : d->second);
  }
  std::map<std::string, double> levels;
  for (const pddl::TypedName& o : problem.objects) {
    if (std::find(o.types.begin(), o.types.end(), "robot") == o.types.end()) continue;
    const double level =
        robot_value(problem, "reserve", o.name) + robot_value(problem, "drain_rate", o.name) * farthest;
    if (level > robot_value(problem, "capacity", o.name)) {
      throw std::invalid_argument("battery: " + o.name + " needs " + std::to_string(level) +
                                  " to reach a dock from the farthest room, more than its capacity");
    }
    levels[o.name] = level;
  }
  return levels;
}

}  // namespace alplan::domains
