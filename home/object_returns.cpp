#include "home/object_returns.h"

namespace alplan::home {
namespace {

repair::ExogenousEvent set(double time, repair::AtomKey atom, bool value, const std::string& description) {
  repair::ExogenousEvent e;
  e.time = time;
  e.atom = std::move(atom);
  e.value = value;
  e.description = description;
  return e;
}

}  // namespace

ObjectReturns::ObjectReturns(const pddl::Problem& home, double return_s) : return_s_(return_s) {
  for (const pddl::Atom& a : home.init) {
    if (a.name == "be" && a.args.size() == 2) room_of_.emplace(a.args[0].name, a.args[1].name);
  }
}

std::vector<repair::ExogenousEvent> ObjectReturns::after_failure(
    const std::vector<repair::ExogenousEvent>& failure) const {
  std::vector<repair::ExogenousEvent> back;
  for (const repair::ExogenousEvent& e : failure) {
    if (e.kind != repair::ExogenousEvent::Kind::SetAtom || e.value || e.atom.size() != 2 || e.atom[0] != "available") {
      continue;
    }
    back.push_back(set(e.time + return_s_, e.atom, true, e.atom[1] + " is back in service"));
  }
  return back;
}

std::vector<repair::ExogenousEvent> ObjectReturns::collect_from(const repair::WorldState& world,
                                                                const std::string& senior, double t) {
  std::vector<repair::ExogenousEvent> back;
  for (const repair::AtomKey& a : world.atoms) {
    if (a.size() != 3 || a[0] != "given" || a[2] != senior) continue;
    const std::string& object = a[1];
    const auto room = room_of_.find(object);
    if (room == room_of_.end()) continue;
    const auto pending = collecting_.find(a);
    if (pending != collecting_.end() && pending->second > t) continue;
    const double at = t + return_s_;
    collecting_[a] = at;
    const std::string why = object + " is collected from " + senior + " and put back in " + room->second;
    back.push_back(set(at, a, false, why));
    back.push_back(set(at, {"filled", object}, false, why));
    back.push_back(set(at, {"available", object}, true, why));
    back.push_back(set(at, {"be", object, room->second}, true, why));
  }
  return back;
}

}  // namespace alplan::home
