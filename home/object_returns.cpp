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

std::string first_room(const pddl::Problem& home, const std::string& object) {
  for (const pddl::Atom& a : home.init) {
    if (a.name == "be" && a.args.size() == 2 && a.args[0].name == object) return a.args[1].name;
  }
  return {};
}

}  // namespace

std::vector<repair::ExogenousEvent> returns_after_failure(const std::vector<repair::ExogenousEvent>& failure,
                                                          double return_s) {
  std::vector<repair::ExogenousEvent> back;
  for (const repair::ExogenousEvent& e : failure) {
    if (e.kind != repair::ExogenousEvent::Kind::SetAtom || e.value || e.atom.size() != 2 || e.atom[0] != "available") {
      continue;
    }
    back.push_back(set(e.time + return_s, e.atom, true, e.atom[1] + " is back in service"));
  }
  return back;
}

std::vector<repair::ExogenousEvent> returns_after_comfort(const repair::WorldState& world, const pddl::Problem& home,
                                                          const std::string& senior, double t, double return_s) {
  std::vector<repair::ExogenousEvent> back;
  for (const repair::AtomKey& a : world.atoms) {
    if (a.size() != 3 || a[0] != "given" || a[2] != senior) continue;
    const std::string& object = a[1];
    const std::string room = first_room(home, object);
    if (room.empty()) continue;
    const double at = t + return_s;
    const std::string why = object + " is collected from " + senior + " and put back in " + room;
    back.push_back(set(at, a, false, why));
    back.push_back(set(at, {"filled", object}, false, why));
    back.push_back(set(at, {"available", object}, true, why));
    back.push_back(set(at, {"be", object, room}, true, why));
  }
  return back;
}

}  // namespace alplan::home
