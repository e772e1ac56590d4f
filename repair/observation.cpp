#include "repair/observation.h"

#include <algorithm>

#include "repair/world_simulator.h"

namespace alplan::repair {
namespace {

constexpr std::pair<ObservationModel, const char*> kModelNames[] = {
    {ObservationModel::Full, "full"}, {ObservationModel::Iot, "iot"}, {ObservationModel::Camera, "camera"}};

bool declared_as(const pddl::TypedName& object, const std::string& type) {
  return std::find(object.types.begin(), object.types.end(), type) != object.types.end();
}

}  // namespace

std::string to_string(ObservationModel model) {
  for (const auto& [m, name] : kModelNames) {
    if (m == model) return name;
  }
  return "?";
}

std::optional<ObservationModel> observation_model(const std::string& name) {
  for (const auto& [m, n] : kModelNames) {
    if (name == n) return m;
  }
  return std::nullopt;
}

SensedObjects sensed_objects(const pddl::Problem& problem, const ObservationOptions& options) {
  SensedObjects out;
  for (const pddl::TypedName& o : problem.objects) {
    out.known.insert(o.name);
    if (declared_as(o, options.robot_type)) out.robots.insert(o.name);
    if (declared_as(o, options.person_type)) out.persons.insert(o.name);
  }
  for (const pddl::Atom& a : problem.init) {
    if (a.name == options.iot_predicate && a.args.size() == 1) out.iot.insert(a.args.front().name);
  }
  return out;
}

std::map<std::string, std::string> locations(const WorldState& state, const std::string& location_predicate) {
  std::map<std::string, std::string> at;
  for (const AtomKey& a : state.atoms) {
    if (a.size() == 3 && a[0] == location_predicate) at[a[1]] = a[2];
  }
  return at;
}

Belief::Belief(const pddl::Problem& problem, ObservationOptions options)
    : options_(std::move(options)),
      objects_(sensed_objects(problem, options_)),
      state_(initial_world(problem)),
      timed_literals_(problem.timed_literals),
      search_(PersonSearchOptions{options_.location_predicate, options_.path_predicate,
                                  options_.distance_function}) {
  std::stable_sort(timed_literals_.begin(), timed_literals_.end(),
                   [](const pddl::TimedInitialLiteral& a, const pddl::TimedInitialLiteral& b) { return a.time < b.time; });
}

std::optional<double> Belief::last_seen(const AtomKey& key) const {
  const auto it = seen_at_.find(key);
  if (it == seen_at_.end()) return std::nullopt;
  return it->second;
}

void Belief::know(const std::string& object) { objects_.known.insert(object); }

void Belief::apply_timed_literals(double t) {
  std::size_t applied = 0;
  for (; applied < timed_literals_.size() && timed_literals_[applied].time <= t; ++applied) {
    const pddl::TimedInitialLiteral& til = timed_literals_[applied];
    AtomKey key{til.atom.name};
    for (const pddl::Term& term : til.atom.args) key.push_back(term.name);
    state_.set(key, til.positive);
  }
  timed_literals_.erase(timed_literals_.begin(), timed_literals_.begin() + static_cast<std::ptrdiff_t>(applied));
}

bool Belief::visible(const AtomKey& key, const View& view) const {
  if (options_.model == ObservationModel::Full || key.size() < 2) return true;
  const std::string& subject = key[1];
  if (objects_.robots.count(subject)) return true;  // the robot knows its own state
  const auto true_place = view.truth_at.find(subject);
  const bool held = view.held.count(subject) != 0;
  const bool has_place = true_place != view.truth_at.end() || view.believed_at.count(subject) || held;
  if (!has_place) return true;  // places, and what no longer has one: the map and the robot's own doing
  if (options_.model == ObservationModel::Iot) {
    if (objects_.persons.count(subject)) return true;  // wristbands and the home's cameras
    if (objects_.iot.count(subject) &&
        (key[0] == options_.location_predicate || key[0] == options_.availability_predicate)) {
      return true;
    }
  }
  if (held) return true;
  if (true_place != view.truth_at.end() && view.rooms.count(true_place->second)) return true;
  // In the room where the robot thought it was, the robot sees it is gone.
  return key[0] == options_.location_predicate && key.size() == 3 && view.rooms.count(key[2]) != 0;
}

bool Belief::record_sightings(const WorldState& truth, const View& view) {
  bool changed = false;
  for (const auto& [thing, place] : view.truth_at) {
    if (objects_.known.count(thing)) continue;
    if (options_.model != ObservationModel::Full && !view.rooms.count(place)) continue;
    auto it = std::find_if(sightings_.begin(), sightings_.end(), [&](const Sighting& s) { return s.object == thing; });
    if (it == sightings_.end()) {
      sightings_.push_back({thing, place, truth.time});
      changed = true;
    } else {
      changed = changed || it->location != place;
      *it = {thing, place, truth.time};
    }
  }
  return changed;
}

bool Belief::observe(const WorldState& truth) {
  apply_timed_literals(truth.time);
  View view;
  view.truth_at = locations(truth, options_.location_predicate);
  view.believed_at = locations(state_, options_.location_predicate);
  for (const std::string& robot : objects_.robots) {
    const auto at = view.truth_at.find(robot);
    if (at != view.truth_at.end()) view.rooms.insert(at->second);
  }
  for (const AtomKey& a : truth.atoms) {
    if (a.size() == 3 && a[0] == options_.holding_predicate && objects_.robots.count(a[1])) view.held.insert(a[2]);
  }
  bool changed = record_sightings(truth, view);
  std::set<AtomKey> keys = truth.atoms;
  keys.insert(state_.atoms.begin(), state_.atoms.end());
  for (const AtomKey& key : keys) {
    if (!visible(key, view)) continue;
    const bool now = truth.holds(key);
    if (now != state_.holds(key)) {
      state_.set(key, now);
      if (key.size() < 2 || !objects_.robots.count(key[1])) changed = true;
    }
    seen_at_[key] = truth.time;
  }
  for (const auto& [key, value] : truth.values) state_.values[key] = value;
  state_.time = std::max(state_.time, truth.time);
  if (options_.search_lost_persons && search_.update(objects_.persons, view.rooms, truth.time, state_)) changed = true;
  news_ += changed;
  return changed;
}

void Belief::told(const AtomKey& key, bool value) { state_.set(key, value); }

void Belief::learned(const AtomKey& key, bool value) {
  if (state_.holds(key) == value) return;
  state_.set(key, value);
  ++news_;
}

void Belief::expect(const pddl::TimedInitialLiteral& literal) {
  // A home and its mission's monitor may both be told of one window.
  if (std::any_of(timed_literals_.begin(), timed_literals_.end(),
                  [&](const pddl::TimedInitialLiteral& l) { return same_literal(l, literal); })) {
    return;
  }
  const auto later = std::upper_bound(
      timed_literals_.begin(), timed_literals_.end(), literal.time,
      [](double t, const pddl::TimedInitialLiteral& l) { return t < l.time; });
  timed_literals_.insert(later, literal);
}

void Belief::withdraw(const pddl::TimedInitialLiteral& literal) {
  std::erase_if(timed_literals_, [&](const pddl::TimedInitialLiteral& l) { return same_literal(l, literal); });
}

void Belief::act(const GroundTask& task, ActionId action, bool start, double duration) {
  apply_snap_effects(task, action, start, duration, state_);
}

}  // namespace alplan::repair
