#include "repair/observation.h"

#include <catch2/catch.hpp>

#include "domains/pddl_files.h"
#include "repair/world_simulator.h"
#include "tests/support/test_paths.h"

using namespace alplan;
using repair::AtomKey;
using repair::Belief;
using repair::ObservationModel;

namespace {

const std::string kDir = test::source_dir() + "/domains/assisted_living";

pddl::Problem paper_home() { return *domains::load_pddl(kDir + "/domain.pddl", kDir + "/paper-scenario-1.pddl").problem; }

// The paper's home, a minute in: the robot in corridor2, an untagged mug in
// the kitchen, glass 5 (tagged) and the mug both unavailable, senior1 in the
// library, and a drum (unknown to the problem) in the dining room.
repair::WorldState changed_world(const pddl::Problem& problem) {
  repair::WorldState w = repair::initial_world(problem);
  w.time = 60.0;
  w.set({"be", "robot1", "bedroom1"}, false);
  w.set({"be", "robot1", "corridor2"}, true);
  w.set({"available", "glass_id05"}, false);
  w.set({"be", "senior1", "bedroom1"}, false);
  w.set({"be", "senior1", "library1"}, true);
  w.set({"be", "drum_x", "dinning_room1"}, true);
  w.set({"available", "drum_x"}, true);
  return w;
}

Belief belief(const pddl::Problem& problem, ObservationModel model) {
  repair::ObservationOptions options;
  options.model = model;
  return Belief(problem, options);
}

}  // namespace

TEST_CASE("observation models: names for the command line") {
  for (ObservationModel m : {ObservationModel::Full, ObservationModel::Iot, ObservationModel::Camera}) {
    CHECK(repair::observation_model(repair::to_string(m)) == m);
  }
  CHECK_FALSE(repair::observation_model("psychic"));
}

TEST_CASE("the problem says which objects carry an IoT tag") {
  const repair::SensedObjects objects = repair::sensed_objects(paper_home(), {});
  CHECK(objects.iot.count("glass_id05"));
  CHECK(objects.iot.count("tv_id01"));
  CHECK(objects.robots == std::set<std::string>{"robot1"});
  CHECK(objects.persons.count("senior8"));
}

TEST_CASE("full: the monitor sees everything, unknown things included") {
  const pddl::Problem problem = paper_home();
  Belief b = belief(problem, ObservationModel::Full);
  CHECK(b.observe(changed_world(problem)));
  CHECK_FALSE(b.state().holds({"available", "glass_id05"}));
  CHECK(b.state().holds({"be", "senior1", "library1"}));
  REQUIRE(b.sightings().size() == 1);
  CHECK(b.sightings()[0].object == "drum_x");
  CHECK(b.sightings()[0].location == "dinning_room1");
}

TEST_CASE("iot: tags and wristbands report from afar, the rest only in the robot room") {
  const pddl::Problem problem = paper_home();
  Belief b = belief(problem, ObservationModel::Iot);
  repair::WorldState w = changed_world(problem);
  CHECK(b.observe(w));
  CHECK_FALSE(b.state().holds({"available", "glass_id05"}));  // its tag says so
  CHECK(b.state().holds({"be", "senior1", "library1"}));        // the wristband
  CHECK(b.state().holds({"be", "robot1", "corridor2"}));        // itself
  CHECK(b.sightings().empty());                                // the drum is in another room
  CHECK(b.last_seen({"available", "glass_id05"}) == Approx(60.0));
}

TEST_CASE("iot: an untagged object is assumed as last seen until the robot is in its room") {
  pddl::Problem problem = paper_home();
  // The tags of glass 6 are removed: it is seen by the camera only.
  std::erase_if(problem.init, [](const pddl::Atom& a) {
    return a.name == "iot_tagged" && a.args.front().name == "glass_id06";
  });
  Belief b = belief(problem, ObservationModel::Iot);
  repair::WorldState w = repair::initial_world(problem);
  w.time = 10.0;
  w.set({"available", "glass_id06"}, false);
  b.observe(w);
  CHECK(b.state().holds({"available", "glass_id06"}));  // assumed
  CHECK_FALSE(b.last_seen({"available", "glass_id06"}));
  // The robot reaches the kitchen: now it sees.
  w.time = 20.0;
  w.set({"be", "robot1", "bedroom1"}, false);
  w.set({"be", "robot1", "kitchen1"}, true);
  CHECK(b.observe(w));
  CHECK_FALSE(b.state().holds({"available", "glass_id06"}));
  CHECK(b.last_seen({"available", "glass_id06"}) == Approx(20.0));
}

TEST_CASE("iot: the robot sees an unknown thing in its room and remembers where and when") {
  const pddl::Problem problem = paper_home();
  Belief b = belief(problem, ObservationModel::Iot);
  repair::WorldState w = changed_world(problem);
  w.set({"be", "robot1", "corridor2"}, false);
  w.set({"be", "robot1", "dinning_room1"}, true);
  CHECK(b.observe(w));
  REQUIRE(b.sightings().size() == 1);
  CHECK(b.sightings()[0].time == Approx(60.0));
  // It leaves; the sighting stays, with its age.
  w.time = 90.0;
  w.set({"be", "robot1", "dinning_room1"}, false);
  w.set({"be", "robot1", "kitchen1"}, true);
  b.observe(w);
  REQUIRE(b.sightings().size() == 1);
  CHECK(b.sightings()[0].time == Approx(60.0));
  CHECK(b.state().holds({"be", "drum_x", "dinning_room1"}));
  b.know("drum_x");  // integrated into the problem: no longer a sighting to report
  w.time = 100.0;
  w.set({"be", "robot1", "kitchen1"}, false);
  w.set({"be", "robot1", "dinning_room1"}, true);
  b.observe(w);
  CHECK(b.sightings().size() == 1);
}

TEST_CASE("camera: nothing from afar, not even a tag or a wristband") {
  const pddl::Problem problem = paper_home();
  Belief b = belief(problem, ObservationModel::Camera);
  b.observe(changed_world(problem));
  CHECK(b.state().holds({"available", "glass_id05"}));       // assumed available
  CHECK(b.state().holds({"be", "senior1", "bedroom1"}));     // assumed where it was
  CHECK(b.state().holds({"be", "robot1", "corridor2"}));     // the robot knows itself
  // In the room where it thought senior1 was, it sees senior1 is gone.
  repair::WorldState w = changed_world(problem);
  w.set({"be", "robot1", "corridor2"}, false);
  w.set({"be", "robot1", "bedroom1"}, true);
  b.observe(w);
  CHECK_FALSE(b.state().holds({"be", "senior1", "bedroom1"}));
  CHECK_FALSE(b.state().holds({"be", "senior1", "library1"}));  // but not where they went
  // It searches: senior1 is assumed in the nearest place it has not looked
  // in, corridor1 (30 s away), a guess its camera will check.
  CHECK(b.state().holds({"be", "senior1", "corridor1"}));
  CHECK(b.search().assumed("(be senior1 corridor1)"));
  CHECK_FALSE(b.last_seen({"be", "senior1", "corridor1"}));
}

TEST_CASE("camera: without the search, a senior who left is believed nowhere") {
  const pddl::Problem problem = paper_home();
  repair::ObservationOptions options;
  options.model = ObservationModel::Camera;
  options.search_lost_persons = false;
  Belief b(problem, options);
  repair::WorldState w = changed_world(problem);
  w.set({"be", "robot1", "corridor2"}, false);
  w.set({"be", "robot1", "bedroom1"}, true);
  b.observe(w);
  for (const AtomKey& a : b.state().atoms) CHECK_FALSE((a.size() == 3 && a[0] == "be" && a[1] == "senior1"));
}

TEST_CASE("iot: the wristband places every senior, so nobody is searched for") {
  const pddl::Problem problem = paper_home();
  Belief b = belief(problem, ObservationModel::Iot);
  repair::WorldState w = changed_world(problem);
  w.set({"be", "robot1", "corridor2"}, false);
  w.set({"be", "robot1", "bedroom1"}, true);
  b.observe(w);
  CHECK(b.state().holds({"be", "senior1", "library1"}));
  CHECK_FALSE(b.search().status("senior1"));
}

TEST_CASE("the belief follows the care plan's timed literals even out of view") {
  const pddl::Problem problem = paper_home();
  Belief b = belief(problem, ObservationModel::Camera);
  repair::WorldState w = repair::initial_world(problem);
  w.set({"be", "robot1", "bedroom1"}, false);
  w.set({"be", "robot1", "kitchen1"}, true);
  w.time = 700.0;  // the hydration window closed at 600
  b.observe(w);
  CHECK_FALSE(b.state().holds({"hydration_time", "senior1"}));
}
