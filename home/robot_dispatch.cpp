#include "home/robot_dispatch.h"

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace alplan::home {
namespace {

constexpr double kUnreachable = std::numeric_limits<double>::infinity();

bool names(const pddl::Atom& atom, const std::set<std::string>& objects) {
  return std::any_of(atom.args.begin(), atom.args.end(), [&](const pddl::Term& t) { return objects.count(t.name); });
}

}  // namespace

TravelTimes::TravelTimes(const pddl::Problem& problem) {
  std::map<std::pair<std::string, std::string>, double> time;
  for (const pddl::NumericFact& f : problem.numeric_init) {
    if (f.function.name == "moving_time" && f.function.args.size() == 2) {
      time[{f.function.args[0].name, f.function.args[1].name}] = f.value;
    }
  }
  for (const pddl::Atom& a : problem.init) {
    if (a.name == "path" && a.args.size() == 2) {
      const auto t = time.find({a.args[0].name, a.args[1].name});
      into_[a.args[1].name].emplace_back(a.args[0].name, t == time.end() ? 1.0 : t->second);
    }
    if (a.name == "be" && a.args.size() == 2) room_of_[a.args[0].name] = a.args[1].name;
  }
}

std::optional<std::string> TravelTimes::room_of(const std::string& thing) const {
  const auto it = room_of_.find(thing);
  return it == room_of_.end() ? std::nullopt : std::optional<std::string>(it->second);
}

std::map<std::string, double> TravelTimes::times_to(const std::string& room) const {
  return repair::shortest_times(into_, {room});  // along the ways reversed
}

std::vector<std::string> dispatch_robots(const pddl::Problem& problem, const std::vector<std::string>& robots,
                                         std::vector<Call> calls) {
  const TravelTimes travel(problem);
  std::stable_sort(calls.begin(), calls.end(), [](const Call& a, const Call& b) { return a.window_end < b.window_end; });
  std::vector<std::string> free;
  for (const std::string& r : robots) {
    if (travel.room_of(r)) free.push_back(r);
  }
  std::vector<std::string> chosen;
  std::set<std::string> seen_seniors;
  for (const Call& call : calls) {
    if (free.empty()) break;
    if (!seen_seniors.insert(call.senior).second) continue;
    const std::optional<std::string> room = travel.room_of(call.senior);
    if (!room) continue;
    const std::map<std::string, double> to_senior = travel.times_to(*room);
    const auto time_of = [&](const std::string& robot) {
      const auto t = to_senior.find(*travel.room_of(robot));
      return t == to_senior.end() ? kUnreachable : t->second;
    };
    // The nearest; ties to the robot named first, so that runs repeat.
    const auto nearest = std::min_element(free.begin(), free.end(), [&](const std::string& a, const std::string& b) {
      return time_of(a) < time_of(b);
    });
    chosen.push_back(*nearest);
    free.erase(nearest);
  }
  return chosen;
}

pddl::Problem with_robots_only(const pddl::Problem& problem, const std::vector<std::string>& all_robots,
                               const std::vector<std::string>& keep) {
  std::set<std::string> dropped;
  for (const std::string& r : all_robots) {
    if (std::find(keep.begin(), keep.end(), r) == keep.end()) dropped.insert(r);
  }
  if (dropped.empty()) return problem;
  pddl::Problem out = problem;
  std::erase_if(out.objects, [&](const pddl::TypedName& o) { return dropped.count(o.name) != 0; });
  std::erase_if(out.init, [&](const pddl::Atom& a) { return names(a, dropped); });
  std::erase_if(out.numeric_init, [&](const pddl::NumericFact& f) { return names(f.function, dropped); });
  std::erase_if(out.timed_literals, [&](const pddl::TimedInitialLiteral& t) { return names(t.atom, dropped); });
  return out;
}

}  // namespace alplan::home
