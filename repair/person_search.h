// Where to look for a person the robot has lost sight of. With only its
// camera (observation.h, ObservationModel::Camera) the robot learns that a
// senior has left the room it believed them in when it gets there, and
// nothing of where they went: no plan can reach a senior who is nowhere, so
// every strategy gave up at once, and the camera model's cost in the repair
// study was that of a robot that never looks.
//
// A robot that looks commits to an assumption, as assumptive planning does
// (Nourbakhsh and Genesereth, "Assumptive planning and execution: a simple,
// working robot architecture", Autonomous Robots 3, 1996): it plans as if a
// guess were a fact, and the monitor checks the guess like any other fact,
// so the loop of failure and repair needs nothing new. The guess: the
// person is in the nearest place, by the home's travel times from the
// robots, that no robot has looked in since the person was lost. The guess goes into the belief; the robot's
// plan takes it there; the camera confirms it (the person is seen, and the
// search ends) or refutes it (the place is empty, and the next guess is
// made at once). Each place is looked in once per loss: when all have been
// looked in, no guess is made and the planner reports that no plan reaches
// the person, so the search ends.
//
// Nearest first is a greedy tour, not an optimal one, and it uses no prior
// on where people go: the only one at hand would be the study's own rule
// (a senior walks to a private room drawn uniformly), which a robot in a
// real home does not know, and using it would flatter the camera.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "repair/world_state.h"

namespace alplan::repair {

struct PersonSearchOptions {
  std::string location_predicate = "be";       // (be thing place)
  std::string path_predicate = "path";         // (path from to): the places and the ways between them
  std::string distance_function = "moving_time";  // (moving_time from to); 1 per way where none
};

class PersonSearch {
 public:
  explicit PersonSearch(PersonSearchOptions options) : options_(std::move(options)) {}

  // After an observation at `time`: `rooms` are the places the robots are
  // in (and so have looked in); distances are measured from them, or from
  // the last places they were in while they move.
  // Ends the search for each person the belief places where no guess put
  // them (seen), rules out what was looked in for the others, and puts each
  // person the belief places nowhere in the nearest place not looked in.
  // Returns true when a guess changed.
  bool update(const std::set<std::string>& persons, const std::set<std::string>& rooms, double time,
              WorldState& belief);

  // A location fact the search assumed (and perhaps saw refuted) for a
  // person it is still looking for: a failure of it is a step of the search.
  bool assumed(const std::string& condition) const;
  // For an explanation: whom the search is for, when they were lost, where
  // it has looked, and where it looks now (nothing once it has looked
  // everywhere).
  struct Status {
    std::string person;
    double lost_at = 0.0;
    std::vector<std::string> looked_in;  // in the order looked in
    std::optional<std::string> guess;
  };
  std::optional<Status> status(const std::string& person) const;

 private:
  struct Search {
    double lost_at = 0.0;
    std::vector<std::string> looked_in;
    std::optional<std::string> guess;
    std::set<std::string> assumed;  // every guess made, as PDDL text
  };
  std::optional<std::string> nearest_unsearched(const Search& search, const std::set<std::string>& from,
                                                const WorldState& belief) const;

  PersonSearchOptions options_;
  std::map<std::string, Search> searches_;
  std::set<std::string> last_rooms_;
};

}  // namespace alplan::repair
