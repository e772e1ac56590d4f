// The simulated world does what its physics allows (world_simulator.h): an
// action whose conditions the world contradicts changes nothing, and the
// robot's executive hears which literal stopped it.
#include "repair/world_simulator.h"

#include <catch2/catch.hpp>

#include "domains/pddl_files.h"
#include "planner/grounder.h"
#include "tests/support/ground_names.h"
#include "tests/support/test_paths.h"

namespace alplan::repair {
namespace {

struct Home {
  domains::LoadedFiles files;
  std::shared_ptr<const GroundTask> task;
};

Home paper_home() {
  const std::string dir = test::source_dir() + "/domains/assisted_living/";
  domains::LoadedFiles files = domains::load_pddl(dir + "domain.pddl", dir + "paper-scenario-2.pddl");
  std::shared_ptr<const GroundTask> task = ground(*files.domain, *files.problem);
  return {std::move(files), std::move(task)};
}

// The robot holds the guitar in bedroom1, the senior's room in the
// problem, as the plan would have it before its handover.
WorldState holding_guitar_in_bedroom1(const pddl::Problem& problem) {
  WorldState there = initial_world(problem);
  for (const AtomKey& a : std::vector<AtomKey>(there.atoms.begin(), there.atoms.end())) {
    if (a.size() == 3 && a[0] == "be" && (a[1] == "robot1" || a[1] == "guitar_id01")) there.set(a, false);
  }
  there.set({"be", "robot1", "bedroom1"}, true);
  there.set({"holding", "robot1", "guitar_id01"}, true);
  return there;
}

}  // namespace

TEST_CASE("a handover to a senior who is not in the room changes nothing, and says why") {
  const Home h = paper_home();
  const ActionId give = test::action_named(*h.task, "(give robot1 senior1 guitar_id01 bedroom1)");
  // The senior has left before the handover.
  WorldState there = holding_guitar_in_bedroom1(*h.files.problem);
  WorldSimulator sim(there, senior_moves(1.0, "senior1", "bedroom1", "sunroom1"));
  sim.advance(2.0);
  REQUIRE_FALSE(sim.holds({"be", "senior1", "bedroom1"}));
  sim.start_action(*h.task, give, 2.0, 10.0);
  // It does not begin: the robot keeps the guitar.
  CHECK(sim.holds({"holding", "robot1", "guitar_id01"}));
  sim.advance(12.0);
  CHECK(sim.end_action(*h.task, give, 12.0));
  CHECK_FALSE(sim.holds({"given", "guitar_id01", "senior1"}));
  REQUIRE(sim.void_actions().size() == 1);
  const VoidAction& v = sim.void_actions().front();
  CHECK(v.action == "(give robot1 senior1 guitar_id01 bedroom1)");
  CHECK(v.literal == AtomKey{"be", "senior1", "bedroom1"});
  CHECK_FALSE(v.holds);
  CHECK(v.why == "(be senior1 bedroom1) did not hold as it began");
  CHECK(sim.void_actions_since(1).empty());
  CHECK(sim.void_actions_since(0).size() == 1);
}

TEST_CASE("a senior who walks away in the middle of a handover does not receive the item") {
  const Home h = paper_home();
  WorldState there = holding_guitar_in_bedroom1(*h.files.problem);
  REQUIRE(there.holds({"be", "senior1", "bedroom1"}));
  WorldSimulator sim(there, senior_moves(5.0, "senior1", "bedroom1", "sunroom1"));
  const ActionId give = test::action_named(*h.task, "(give robot1 senior1 guitar_id01 bedroom1)");
  sim.start_action(*h.task, give, 0.0, 10.0);
  CHECK_FALSE(sim.holds({"holding", "robot1", "guitar_id01"}));  // it began: the hand is open
  sim.advance(10.0);
  CHECK(sim.end_action(*h.task, give, 10.0));
  CHECK_FALSE(sim.holds({"given", "guitar_id01", "senior1"}));
  REQUIRE(sim.void_actions().size() == 1);
  CHECK(sim.void_actions().front().why == "(be senior1 bedroom1) stopped holding while it ran");
  CHECK(sim.void_actions().front().time == 5.0);
}

TEST_CASE("an action whose conditions hold does what it says, and nothing is void") {
  const Home h = paper_home();
  WorldState there = holding_guitar_in_bedroom1(*h.files.problem);
  WorldSimulator sim(there, {});
  const ActionId give = test::action_named(*h.task, "(give robot1 senior1 guitar_id01 bedroom1)");
  sim.start_action(*h.task, give, 0.0, 10.0);
  sim.advance(10.0);
  CHECK(sim.end_action(*h.task, give, 10.0));
  CHECK(sim.holds({"given", "guitar_id01", "senior1"}));
  CHECK(sim.void_actions().empty());
}

}  // namespace alplan::repair
