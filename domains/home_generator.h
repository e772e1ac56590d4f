// Larger assisted-living homes for experiments (`alplan gen home`): a random
// connected layout (corridors in a tree, rooms hanging off corridors, the
// kitchen off a dining room as in the paper's home), objects where they
// belong, seniors in their rooms with emotions, and comfort windows as timed
// initial literals whose urgency follows the paper's Discussion: a
// terrified senior's window is shorter than a sad or bored one's.
// Deterministic: the same options give the same problem, byte for byte.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace alplan::domains {

struct HomeOptions {
  int rooms = 12;    // besides corridors; at least 4 (kitchen, dining, music, library)
  int seniors = 8;
  int robots = 1;
  int objects = 16;  // portable objects: vessels, instruments, reading, puzzles, screens
  int stressed = 1;  // seniors with a goal (the rest are calm)
  // The share of portable objects with an IoT tag, (iot_tagged o): they
  // report their place and availability; the rest are seen by the robot's
  // camera only (repair/observation.h). Drawn from its own stream, so the
  // layout and objects of a seed do not depend on it.
  double iot_share = 0.5;
  // The share of portable objects left away from their room (a glass on a
  // bedside table, a book in a sunroom), each in a room drawn uniformly among
  // the others. 0 keeps every object of a type in its type's one room, where
  // a replacement for a lost object always stands beside it; a spread type
  // makes what the robot knows before it goes decide where it goes. Its own
  // stream too: a seed's home at 0 is the home it always was.
  double scatter = 0.0;
  std::uint64_t seed = 1;
};

struct StressedSenior {
  std::string name;
  std::string emotion;  // terrified, sad or bored
  std::string goal;     // (soothed s), (cheerful s), (entertained s)
  std::string room;
};

struct GeneratedHome {
  std::string problem;  // PDDL text for domains/assisted_living/domain.pddl
  std::vector<StressedSenior> stressed;
  std::vector<std::string> rooms;
  // Portable objects: name, type, room.
  struct Object {
    std::string name, type, room;
    bool available = true;
    bool iot = false;
  };
  std::vector<Object> objects;
};

// Throws std::invalid_argument when the options cannot make a home.
GeneratedHome generate_home(const HomeOptions& options);

}  // namespace alplan::domains
