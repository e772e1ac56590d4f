#include "repair/world_simulator.h"

#include <algorithm>
#include <cmath>

#include "planner/formula_evaluation.h"
#include "planner/happening_effects.h"

namespace alplan::repair {
namespace {

// Running actions ordered by when they are expected to end (by name among
// equal ends, as the map holds them).
std::vector<ActionInProgress> by_end(const std::map<std::string, ActionInProgress>& running) {
  std::vector<ActionInProgress> out;
  for (const auto& [name, a] : running) out.push_back(a);
  const auto earlier = [](const ActionInProgress& a, const ActionInProgress& b) {
    return a.expected_end < b.expected_end;
  };
  std::stable_sort(out.begin(), out.end(), earlier);
  return out;
}

}  // namespace

ExogenousEvent becomes_unavailable(double time, const std::string& object) {
  ExogenousEvent e;
  e.time = time;
  e.atom = {"available", object};
  e.value = false;
  e.description = object + " becomes unavailable";
  return e;
}

ExogenousEvent object_appears(double time, const RecognizedObject& object) {
  ExogenousEvent e;
  e.time = time;
  e.kind = ExogenousEvent::Kind::NewObject;
  e.object = object;
  e.description = "a " + object.type + " (" + object.name + ") appears in " + object.location;
  return e;
}

std::vector<ExogenousEvent> senior_moves(double time, const std::string& senior, const std::string& from,
                                         const std::string& to) {
  ExogenousEvent leave{time, ExogenousEvent::Kind::SetAtom, {"be", senior, from}, false, {}, {}, 0.0, {}};
  ExogenousEvent arrive{time, ExogenousEvent::Kind::SetAtom, {"be", senior, to}, true, {}, {}, 0.0, {}};
  leave.description = senior + " moves from " + from + " to " + to;
  arrive.description = leave.description;
  return {leave, arrive};
}

std::vector<ExogenousEvent> emotion_changes(double time, const std::string& senior, const std::string& from,
                                            const std::string& to) {
  ExogenousEvent stop{time, ExogenousEvent::Kind::SetAtom, {from, senior}, false, {}, {}, 0.0, {}};
  ExogenousEvent begin{time, ExogenousEvent::Kind::SetAtom, {to, senior}, true, {}, {}, 0.0, {}};
  stop.description = senior + " is no longer " + from + " but " + to;
  begin.description = stop.description;
  return {stop, begin};
}

ExogenousEvent action_overruns(const std::string& action, double extra) {
  ExogenousEvent e;
  e.kind = ExogenousEvent::Kind::Delay;
  e.action = action;
  e.extra = extra;
  e.description = action + " takes " + std::to_string(extra) + " longer than planned";
  return e;
}

WorldState initial_world(const pddl::Problem& problem) {
  WorldState world;
  for (const pddl::Atom& a : problem.init) world.atoms.insert(key_of(a));
  for (const pddl::NumericFact& f : problem.numeric_init) world.values[key_of(f.function)] = f.value;
  return world;
}

std::vector<ExogenousEvent> timed_literal_events(const pddl::Problem& problem) {
  std::vector<ExogenousEvent> events;
  for (const pddl::TimedInitialLiteral& til : problem.timed_literals) {
    ExogenousEvent e;
    e.time = til.time;
    e.atom = key_of(til.atom);
    e.value = til.positive;
    e.description = "timed literal " + std::string(til.positive ? "" : "(not ") + to_string(e.atom) +
                    (til.positive ? "" : ")");
    events.push_back(e);
  }
  return events;
}

WorldSimulator::WorldSimulator(WorldState initial, std::vector<ExogenousEvent> events)
    : world_(std::move(initial)), pending_(std::move(events)) {
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const ExogenousEvent& a, const ExogenousEvent& b) { return a.time < b.time; });
}

void WorldSimulator::schedule(const std::vector<ExogenousEvent>& events) {
  pending_.insert(pending_.end(), events.begin(), events.end());
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const ExogenousEvent& a, const ExogenousEvent& b) { return a.time < b.time; });
}

void WorldSimulator::cancel(const AtomKey& atom, bool value, double time) {
  std::erase_if(pending_, [&](const ExogenousEvent& e) {
    return e.atom == atom && e.value == value && std::abs(e.time - time) < 1e-9;
  });
}

void WorldSimulator::release(const std::string& action) {
  const auto it = running_.find(action);
  if (it == running_.end()) return;
  const auto overrun = overruns_.find(action);
  if (overrun != overruns_.end()) {  // it was to overrun when its end came: it still does
    it->second.expected_end += overrun->second;
    overruns_.erase(overrun);
  }
  overrunning_.insert(action);  // advance() ends it at its expected end
}

void WorldSimulator::halt(const std::string& action) {
  invariants_.erase(action);
  void_.erase(action);
  running_.erase(action);
  durations_.erase(action);
  overrunning_.erase(action);
  overruns_.erase(action);
}

void WorldSimulator::finish(const ActionInProgress& a) {
  flow_until(a.expected_end);
  invariants_.erase(a.name);
  if (void_.erase(a.name) == 0) {
    for (const AtomKey& d : a.dels) world_.set(d, false);
    for (const AtomKey& k : a.adds) world_.set(k, true);
  }
  // Its change stops here: the others flow on without it.
  running_.erase(a.name);
  check_invariants(a.expected_end);
}

void WorldSimulator::flow_until(double t) {
  if (t <= world_.time) return;
  const double elapsed = t - world_.time;
  for (const auto& [name, a] : running_) {
    for (const auto& [key, rate] : a.rates) {
      double& value = world_.values[key];
      const auto [low, fresh] = lowest_.try_emplace(key, value);
      value += rate * elapsed;
      // Change is linear between two looks: its ends are its extremes.
      low->second = std::min(low->second, value);
    }
  }
  world_.time = t;
}

void WorldSimulator::apply(const ExogenousEvent& e) {
  switch (e.kind) {
    case ExogenousEvent::Kind::SetAtom: world_.set(e.atom, e.value); break;
    case ExogenousEvent::Kind::NewObject:
      appeared_.push_back(e.object);
      world_.set({"be", e.object.name, e.object.location}, true);
      world_.set({"available", e.object.name}, true);
      break;
    case ExogenousEvent::Kind::Delay: overruns_[e.action] += e.extra; break;
  }
  applied_.push_back(e);
}

void WorldSimulator::advance(double t) {
  while (!pending_.empty() && pending_.front().time <= t) {
    const double at = pending_.front().time;
    apply(pending_.front());
    pending_.erase(pending_.begin());
    check_invariants(at);
  }
  // Overrunning actions finish when they finish, in the order they do (the
  // values flow up to each end); the others when the monitor dispatches
  // their ends.
  for (const ActionInProgress& a : by_end(running_)) {
    if (overrunning_.count(a.name) && a.expected_end <= t) {
      overrunning_.erase(a.name);
      finish(a);
    }
  }
  flow_until(t);
  world_.time = std::max(world_.time, t);
}

std::optional<VoidAction> WorldSimulator::contradicted(const GroundTask& task, const StateMapping& mapping,
                                                       const ExplicitState& state, const ConditionSet& c,
                                                       const std::string& when) {
  auto literal = [&](FactId f, bool holds) {
    VoidAction v;
    if (!task.is_derived(f)) v.literal = mapping.fact_key(f);
    v.holds = holds;
    v.why = (holds ? "(not " + task.fact_name(f) + ")" : task.fact_name(f)) + " " + when;
    return v;
  };
  for (FactId f : c.positive) {
    if (!state.fact(f)) return literal(f, false);
  }
  for (FactId f : c.negative) {
    if (state.fact(f)) return literal(f, true);
  }
  return std::nullopt;
}

std::optional<VoidAction> WorldSimulator::try_snap(const GroundTask& task, const StateMapping& mapping,
                                                   ActionId action, bool start, double duration) {
  const GroundAction& a = task.actions[action];
  ExplicitState state = mapping.to_explicit(world_);
  if (auto failed = contradicted(task, mapping, state, start ? a.at_start : a.at_end,
                                 start ? "did not hold at its start" : "did not hold at its end")) {
    return failed;
  }
  EvaluationContext context;
  context.duration = duration;
  apply_happening(task, start ? a.start : a.end, state, context);
  if (start && a.durative) {
    // Over all: from just after the start, so the start's own effects count.
    derive(task, state);
    if (auto broken = contradicted(task, mapping, state, a.over_all, "did not hold as it began")) return broken;
  }
  mapping.write_back(state, world_);
  return std::nullopt;
}

void WorldSimulator::void_action(VoidAction v, const std::string& name, double t) {
  v.time = t;
  v.action = name;
  void_actions_.push_back(std::move(v));
  void_.insert(name);
}

std::vector<VoidAction> WorldSimulator::void_actions_since(std::size_t first) const {
  if (first >= void_actions_.size()) return {};
  return {void_actions_.begin() + static_cast<std::ptrdiff_t>(first), void_actions_.end()};
}

void WorldSimulator::check_invariants(double t) {
  for (const auto& [name, invariant] : invariants_) {
    if (void_.count(name)) continue;
    for (const auto& [keys, value] : {std::pair{&invariant.positive, true}, std::pair{&invariant.negative, false}}) {
      for (const AtomKey& k : *keys) {
        if (world_.holds(k) == value) continue;
        VoidAction v;
        v.literal = k;
        v.holds = !value;
        v.why = (value ? to_string(k) : "(not " + to_string(k) + ")") + " stopped holding while it ran";
        void_action(std::move(v), name, t);
        break;
      }
      if (void_.count(name)) break;
    }
  }
}

void WorldSimulator::start_action(const GroundTask& task, ActionId action, double t, double duration) {
  flow_until(t);
  // Rates are fixed in the state the action starts in, before its start's
  // effects (PDDL 2.1; the validator does the same).
  std::vector<std::pair<AtomKey, double>> rates = continuous_rates(task, action, duration, world_);
  const GroundAction& a = task.actions[action];
  const std::string name = task.action_name(a);
  const StateMapping mapping(task);
  void_.erase(name);
  if (std::optional<VoidAction> failed = try_snap(task, mapping, action, true, duration)) {
    // It does not begin: nothing changes now and nothing at its end (the
    // robot keeps the item it would have handed to no one).
    void_action(std::move(*failed), name, t);
    rates.clear();
  } else {
    check_invariants(t);  // of the others: the robot's own start may break one
  }
  world_.time = std::max(world_.time, t);
  if (!a.durative) {
    void_.erase(name);  // instantaneous: nothing more to come
    return;
  }
  Invariant invariant;
  for (FactId f : a.over_all.positive) {
    if (!task.is_derived(f)) invariant.positive.push_back(mapping.fact_key(f));
  }
  for (FactId f : a.over_all.negative) {
    if (!task.is_derived(f)) invariant.negative.push_back(mapping.fact_key(f));
  }
  invariants_[name] = std::move(invariant);
  ActionInProgress p;
  p.rates = std::move(rates);
  p.name = name;
  p.expected_end = t + duration;
  for (FactId f : a.end.add) p.adds.push_back(mapping.fact_key(f));
  for (FactId f : a.end.del) p.dels.push_back(mapping.fact_key(f));
  durations_[p.name] = duration;
  running_[p.name] = std::move(p);
}

bool WorldSimulator::end_action(const GroundTask& task, ActionId action, double t) {
  flow_until(t);
  const std::string name = task.action_name(task.actions[action]);
  auto overrun = overruns_.find(name);
  auto it = running_.find(name);
  if (overrun != overruns_.end() && it != running_.end()) {
    // The action goes on: it will end `extra` later, on its own.
    it->second.expected_end = t + overrun->second;
    overruns_.erase(overrun);
    overrunning_.insert(name);
    return false;
  }
  if (it != running_.end()) running_.erase(it);
  invariants_.erase(name);
  if (void_.erase(name) == 0) {  // one already void ends with no effect
    if (std::optional<VoidAction> failed = try_snap(task, StateMapping(task), action, false, durations_[name])) {
      void_action(std::move(*failed), name, t);
      void_.erase(name);
    } else {
      check_invariants(t);
    }
  }
  world_.time = std::max(world_.time, t);
  return true;
}

std::vector<ActionInProgress> WorldSimulator::in_progress() const {
  std::vector<ActionInProgress> out;
  for (const auto& [name, a] : running_) out.push_back(a);
  return out;
}

std::vector<RecognizedObject> WorldSimulator::recognize(const WorldState& observed, const std::string& location) {
  std::vector<RecognizedObject> seen;
  for (const RecognizedObject& o : appeared_) {
    if (observed.holds({"be", o.name, location})) seen.push_back(o);
  }
  return seen;
}

std::vector<RecognizedObject> WorldSimulator::recognize_sightings(const std::vector<Sighting>& sightings) {
  std::vector<RecognizedObject> seen;
  for (const Sighting& s : sightings) {
    for (const RecognizedObject& o : appeared_) {
      if (o.name != s.object) continue;
      RecognizedObject where = o;
      where.location = s.location;  // where the camera saw it, not where it is now
      where.seen_at = s.time;
      seen.push_back(where);
    }
  }
  return seen;
}

}  // namespace alplan::repair
