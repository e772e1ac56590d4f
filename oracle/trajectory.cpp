#include "oracle/trajectory.h"

#include "pddl_parser/writer.h"

namespace alplan::oracle {
namespace {
using K = pddl::Condition::Kind;
}

TrajectoryMonitor::TrajectoryMonitor(World& world, Comparisons comparisons)
    : world_(world), comparisons_(comparisons) {
  Binding binding;
  if (world.domain().constraints) gather(*world.domain().constraints, binding, -1);
  if (world.problem().constraints) gather(*world.problem().constraints, binding, -1);
}

void TrajectoryMonitor::gather(const pddl::Condition& c, Binding& binding, int preference) {
  switch (c.kind) {
    case K::And:
      for (const pddl::Condition& child : c.children) gather(child, binding, preference);
      return;
    case K::Forall: {
      std::vector<std::vector<std::string>> domains;
      for (const pddl::TypedName& v : c.variables) domains.push_back(world_.objects_of(v.types));
      for (const auto& d : domains) {
        if (d.empty()) return;
      }
      std::vector<std::size_t> index(domains.size(), 0);
      while (true) {
        for (std::size_t k = 0; k < domains.size(); ++k) binding.push(c.variables[k].name, domains[k][index[k]]);
        gather(c.children.front(), binding, preference);
        binding.pop(domains.size());
        std::size_t k = 0;
        while (k < domains.size() && ++index[k] == domains[k].size()) index[k++] = 0;
        if (k == domains.size()) return;
      }
    }
    case K::Preference:
      preferences_.push_back({c.preference_name.empty() ? kAnonymousPreference : c.preference_name, false});
      gather(c.children.front(), binding, static_cast<int>(preferences_.size()) - 1);
      return;
    case K::Always:
    case K::Sometime:
    case K::Within:
    case K::AtMostOnce:
    case K::SometimeAfter:
    case K::SometimeBefore:
    case K::AlwaysWithin:
    case K::HoldDuring:
    case K::HoldAfter:
    case K::Timed: {
      if (c.kind == K::Timed && c.time != pddl::TimeSpecifier::AtEnd) break;
      Constraint constraint;
      constraint.kind = c.kind;
      constraint.first = {&c.children[0], binding};
      constraint.numbers = c.numbers;
      constraint.preference = preference;
      constraint.text = pddl::write_condition(c);
      if (c.children.size() > 1) constraint.second = {&c.children[1], binding};
      constraints_.push_back(std::move(constraint));
      return;
    }
    default: break;
  }
  throw NotJudged("a constraint the reference semantics does not know: " + pddl::write_condition(c));
}

bool TrajectoryMonitor::holds(const Formula& f, const State& state) {
  Binding binding = f.binding;
  Scope scope(world_, state, binding, comparisons_);
  return oracle::holds(*f.condition, scope);
}

bool TrajectoryMonitor::fail(Constraint& c, const std::string& why) {
  if (c.preference >= 0) {
    preferences_[static_cast<std::size_t>(c.preference)].violated = true;
    return true;
  }
  reason_ = c.text + " is violated: " + why;
  return false;
}

bool TrajectoryMonitor::check(Constraint& c, const State& state, double time) {
  const auto when = [&] { return "at time " + pddl::format_number(time); };
  switch (c.kind) {
    case K::Always:
      return holds(c.first, state) || fail(c, when());
    case K::Sometime:
      if (!c.done && holds(c.first, state)) c.done = true;
      return true;
    case K::Within:
      if (c.done) return true;
      if (time > c.numbers[0]) return fail(c, "not met by its deadline");
      if (holds(c.first, state)) c.done = true;
      return true;
    case K::AtMostOnce: {
      const bool now = holds(c.first, state);
      if (c.run == 0 && now) c.run = 1;
      else if (c.run == 1 && !now) c.run = 2;
      else if (c.run == 2 && now) return fail(c, "holds again " + when());
      return true;
    }
    case K::SometimeAfter:
      if (holds(c.first, state)) c.owed = true;
      if (c.owed && holds(c.second, state)) c.owed = false;
      return true;
    case K::SometimeBefore: {
      if (holds(c.first, state) && !c.seen) return fail(c, when() + " before the second formula ever held");
      if (holds(c.second, state)) c.seen = true;
      return true;
    }
    case K::AlwaysWithin: {
      if (holds(c.first, state)) c.deadlines.push_back(time + c.numbers[0]);
      for (double deadline : c.deadlines) {
        if (time > deadline) return fail(c, "not met within " + pddl::format_number(c.numbers[0]));
      }
      if (holds(c.second, state)) c.deadlines.clear();
      return true;
    }
    case K::HoldDuring:
      if (time >= c.numbers[0] && time < c.numbers[1] && !holds(c.first, state)) return fail(c, when());
      return true;
    case K::HoldAfter:
      if (time > c.numbers[0] && !holds(c.first, state)) return fail(c, when());
      return true;
    default: return true;  // at end: at the end
  }
}

bool TrajectoryMonitor::observe(const State& state, double time) {
  for (Constraint& c : constraints_) {
    if (!check(c, state, time)) return false;
  }
  return true;
}

bool TrajectoryMonitor::finish(const State& final_state) {
  for (Constraint& c : constraints_) {
    bool ok = true;
    switch (c.kind) {
      case K::Timed: ok = holds(c.first, final_state) || fail(c, "at the end"); break;
      case K::Sometime: ok = c.done || fail(c, "it never held"); break;
      case K::Within: ok = c.done || fail(c, "it never held"); break;
      case K::AlwaysWithin: ok = c.deadlines.empty() || fail(c, "still owed at the end"); break;
      case K::SometimeAfter: ok = !c.owed || fail(c, "still owed at the end"); break;
      default: break;
    }
    if (!ok) return false;
  }
  return true;
}

void TrajectoryMonitor::add_violations(std::map<std::string, double>& counts) const {
  for (const Preference& p : preferences_) {
    if (p.violated) counts[p.name] += 1.0;
  }
}

}  // namespace alplan::oracle
