// The observation source for experiments: a world that does what the robot
// does (the plan's effects as the monitor dispatches them) and what scripted
// or random exogenous events do — objects become unavailable, new objects
// appear, a senior moves, an emotion changes, an action takes longer than
// planned. It also plays the camera: it reports the new objects visible at
// a location, as the perception library's recognizer will on real images.
//
// The world does what its physics allows, not what it is told: an action
// whose conditions do not hold in the true world when it starts (a pickup of
// a thing that is gone, a handover to a senior who is not in the room), or
// whose invariant breaks while it runs, or whose end condition fails, has no
// effect from then on; the robot spends the action's time and learns of it
// only as its sensors show that the effects did not come. Failing as it
// starts, the action changes nothing; interrupted while it runs, it keeps
// its start's effects and loses its end's (a senior who walks away in the
// middle of a handover does not receive the item). A world that
// granted such effects would let a robot that cannot see the failure reach
// the goal anyway. Only the conditions' facts are physics; numeric
// conditions (a battery kept above its reserve) are the planner's margins,
// which the world does not enforce; a derived fact in an invariant is judged
// at the start and the end only.
#pragma once

#include <map>
#include <set>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "repair/object_recognizer.h"
#include "repair/world.h"

namespace alplan::repair {

struct ExogenousEvent {
  enum class Kind : unsigned char { SetAtom, NewObject, Delay };
  double time = 0.0;
  Kind kind = Kind::SetAtom;
  AtomKey atom;        // SetAtom
  bool value = true;   // SetAtom
  RecognizedObject object;  // NewObject: it appears, available, at its location
  std::string action;  // Delay: "(move robot1 corridor1 bedroom1)"
  double extra = 0.0;  // Delay: how much longer it takes
  std::string description;
};

// Readable constructors for the events experiments use.
ExogenousEvent becomes_unavailable(double time, const std::string& object);
ExogenousEvent object_appears(double time, const RecognizedObject& object);
std::vector<ExogenousEvent> senior_moves(double time, const std::string& senior, const std::string& from,
                                         const std::string& to);
std::vector<ExogenousEvent> emotion_changes(double time, const std::string& senior, const std::string& from,
                                            const std::string& to);
ExogenousEvent action_overruns(const std::string& action, double extra);

// The world a problem's :init describes (atoms and numeric values), at 0.
WorldState initial_world(const pddl::Problem& problem);
// The problem's timed initial literals, as events the world will apply.
std::vector<ExogenousEvent> timed_literal_events(const pddl::Problem& problem);

class WorldSimulator : public World, public ObjectRecognizer {
 public:
  WorldSimulator(WorldState initial, std::vector<ExogenousEvent> events);

  void advance(double t) override;
  WorldState observe() const override { return world_; }
  // One value of the world now (a robot's battery gauge), without copying
  // the state; nothing when the world has no such value.
  std::optional<double> value(const AtomKey& key) const {
    const auto it = world_.values.find(key);
    return it == world_.values.end() ? std::nullopt : std::optional<double>(it->second);
  }
  bool holds(const AtomKey& key) const { return world_.holds(key); }
  void start_action(const GroundTask& task, ActionId action, double t, double duration) override;
  bool end_action(const GroundTask& task, ActionId action, double t) override;
  std::vector<ActionInProgress> in_progress() const override;

  std::vector<RecognizedObject> recognize(const WorldState& observed, const std::string& location) override;
  // The simulator plays a perfect classifier: each thing's type as it made it.
  std::vector<RecognizedObject> recognize_sightings(const std::vector<Sighting>& sightings) override;

  // More events, from now on (a home's deliberation opens comfort windows
  // and draws failures against each new plan).
  void schedule(const std::vector<ExogenousEvent>& events);
  // Events still to come that set `atom` to `value` at `time`, dropped (a
  // window closing for a goal already settled).
  void cancel(const AtomKey& atom, bool value, double time);

  // A running action no one will dispatch the end of (its mission was
  // given up or moved to another robot) ends on its own when expected,
  // late if it overruns: the robot mid-move still arrives.
  void release(const std::string& action);
  // A running action stops where it is and never ends (a robot broken
  // down mid-move): its start's effects stay, its end's never come.
  void halt(const std::string& action);

  // The lowest value each value changed continuously has had so far (a
  // robot's battery at its emptiest), exact: change is linear between the
  // times the world flows to, so the lowest is at one of them.
  const std::map<AtomKey, double>& lowest_values() const { return lowest_; }

  // Events applied so far, in order, for reports.
  const std::vector<ExogenousEvent>& applied() const { return applied_; }
  // The robot's actions that came to nothing, in order.
  const std::vector<VoidAction>& void_actions() const { return void_actions_; }
  std::vector<VoidAction> void_actions_since(std::size_t first) const override;

 private:
  void apply(const ExogenousEvent& e);
  // Moves the values of running actions' continuous effects on to time t.
  void flow_until(double t);
  // An overrunning action ends on its own: the values flow up to its end,
  // then its end's facts change.
  void finish(const ActionInProgress& a);
  // The first literal of `c` that `state` contradicts (its `why` says which,
  // "(be senior1 room)" or "(not (...))", then `when`); nothing when all hold.
  static std::optional<VoidAction> contradicted(const GroundTask& task, const StateMapping& mapping,
                                                const ExplicitState& state, const ConditionSet& c,
                                                const std::string& when);
  // A snap of `action` (its start or its end) done on the world if the world
  // allows it: its condition before its effects and, for a start, its
  // invariant on the state they make, on one explicit state. Nothing changes
  // when either fails; the failure is returned.
  std::optional<VoidAction> try_snap(const GroundTask& task, const StateMapping& mapping, ActionId action,
                                     bool start, double duration);
  void void_action(VoidAction v, const std::string& name, double t);
  // The invariants of the running actions against the world now.
  void check_invariants(double t);

  WorldState world_;
  std::vector<ExogenousEvent> pending_;  // by time
  std::vector<ExogenousEvent> applied_;
  std::vector<RecognizedObject> appeared_;
  std::map<std::string, double> overruns_;            // action name -> extra time
  std::map<std::string, ActionInProgress> running_;  // by name
  std::map<std::string, double> durations_;           // of running actions, for their ends
  std::set<std::string> overrunning_;                 // ends dispatched, not yet happened
  std::map<AtomKey, double> lowest_;                  // of values changed continuously
  // Each running action's over-all facts that the world holds or not
  // (derived ones left out: the world keeps no derived facts).
  struct Invariant {
    std::vector<AtomKey> positive, negative;
  };
  std::map<std::string, Invariant> invariants_;
  std::set<std::string> void_;  // running actions whose end will change nothing
  std::vector<VoidAction> void_actions_;
};

}  // namespace alplan::repair
