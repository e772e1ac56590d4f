// What the monitor can know of the world. The paper's robot learns what its
// sensors tell it (its Sections 5 and 6.3): IoT-tagged objects report their
// availability and place, the seniors' wristbands and the home's cameras
// report where the seniors are and how they feel, and everything else is
// known only once the robot's own camera has seen it. An omniscient monitor
// sees an object fail wherever the robot is, far from the room where a
// substitute could be seen, and so hides what substitution is for.
//
// Three sensor models (ObservationModel):
// - full: the whole true state, every observation (the old behaviour);
// - iot (the default, the paper's): the robot's own state; IoT objects'
//   place and availability; the seniors' places and facts; everything about
//   a thing in the room the robot is in (or that it holds), and the absence
//   of a thing from the room where the robot believed it was;
// - camera: the robot's own state and what its camera sees in its room.
// Facts about places (paths, distances) and numeric values are the home's
// map and the robot's own accounting: known throughout.
//
// Belief keeps what was last seen of every fact and when (its age). A
// condition on a fact out of view is checked against the belief, and again
// when the fact comes into view; the robot's own effects are predicted into
// it when it acts, and the care plan's timed literals when they fall due.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/ground_task.h"
#include "repair/object_recognizer.h"
#include "repair/person_search.h"
#include "repair/world_state.h"

namespace alplan::repair {

enum class ObservationModel : unsigned char { Full, Iot, Camera };

std::string to_string(ObservationModel model);  // "full", "iot", "camera"
std::optional<ObservationModel> observation_model(const std::string& name);

struct ObservationOptions {
  ObservationModel model = ObservationModel::Iot;
  // The domain's vocabulary, the assisted-living domain's by default.
  std::string location_predicate = "be";             // (be thing place)
  std::string availability_predicate = "available";  // (available object)
  std::string holding_predicate = "holding";         // (holding robot object)
  // (iot_tagged o) in the problem's :init marks an object that reports its
  // place and availability itself.
  std::string iot_predicate = "iot_tagged";
  std::string robot_type = "robot";
  std::string person_type = "senior";  // wear wristbands; the home's cameras see them
  // A person the belief places nowhere (the camera saw their room empty) is
  // searched for: assumed in the nearest place not looked in yet
  // (person_search.h). Off, the robot knows no more than that they left.
  bool search_lost_persons = true;
  std::string path_predicate = "path";            // the ways between places
  std::string distance_function = "moving_time";  // their travel times
};

// The problem's objects as the sensors sort them.
struct SensedObjects {
  std::set<std::string> robots, persons, iot, known;
};
SensedObjects sensed_objects(const pddl::Problem& problem, const ObservationOptions& options);

class Belief {
 public:
  // Starts from what the problem says (what perception reported when the
  // goal was made) and knows the care plan's timed literals.
  Belief(const pddl::Problem& problem, ObservationOptions options);

  // Takes in what the sensors report of `truth` at its time. Returns true
  // when something besides the robot's own state changed (a fact of the
  // world, or a new sighting): a reason to think again about a failure.
  bool observe(const WorldState& truth);
  // The robot's own snap, predicted before the sensors confirm it.
  void act(const GroundTask& task, ActionId action, bool start, double duration);
  // New objects integrated into the problem are known from now on.
  void know(const std::string& object);
  // What the deliberation was told, not what the robot saw: a senior's
  // emotion from the home's perception, a comfort window it opened and the
  // literal that will close it.
  void told(const AtomKey& key, bool value);
  // What an aborted action of the robot's showed it (world.h, VoidAction):
  // news, like a sensor's, for a failure waiting to be tried again.
  void learned(const AtomKey& key, bool value);
  void expect(const pddl::TimedInitialLiteral& literal);  // once, however often told
  // A literal expected no more (a goal settled before its window closes).
  void withdraw(const pddl::TimedInitialLiteral& literal);

  const WorldState& state() const { return state_; }
  // How many observations so far showed something new (observe() true):
  // several executions sharing one belief compare it, since only the first
  // to observe a change is told so by observe().
  std::size_t news() const { return news_; }
  // Things the problem does not name that the camera has seen, the latest
  // sighting of each, in the order first seen.
  const std::vector<Sighting>& sightings() const { return sightings_; }
  // When the fact was last in view; nothing if never (it is assumed).
  std::optional<double> last_seen(const AtomKey& key) const;
  ObservationModel model() const { return options_.model; }
  // The searches for persons lost from sight, and the guesses they made.
  const PersonSearch& search() const { return search_; }

 private:
  // What the robot's senses take in at one observation.
  struct View {
    std::set<std::string> rooms;                     // where the robots are
    std::map<std::string, std::string> truth_at;     // where things are
    std::map<std::string, std::string> believed_at;  // where the belief has them
    std::set<std::string> held;                      // by a robot
  };
  bool visible(const AtomKey& key, const View& view) const;
  void apply_timed_literals(double t);
  // True when a new thing is seen, or a known sighting moved.
  bool record_sightings(const WorldState& truth, const View& view);

  ObservationOptions options_;
  SensedObjects objects_;
  WorldState state_;
  std::map<AtomKey, double> seen_at_;
  std::vector<pddl::TimedInitialLiteral> timed_literals_;  // not yet applied, by time
  std::vector<Sighting> sightings_;
  PersonSearch search_;
  std::size_t news_ = 0;
};

// Where each thing is, from the location predicate's atoms.
std::map<std::string, std::string> locations(const WorldState& state, const std::string& location_predicate);

}  // namespace alplan::repair
