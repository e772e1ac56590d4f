#include "home/object_returns.h"

#include <catch2/catch.hpp>

#include <algorithm>

#include "pddl_parser/parser.h"

namespace alplan::home {
namespace {

bool has(const std::vector<repair::ExogenousEvent>& events, double time, const repair::AtomKey& atom, bool value) {
  return std::any_of(events.begin(), events.end(), [&](const repair::ExogenousEvent& e) {
    return e.time == Approx(time) && e.atom == atom && e.value == value;
  });
}

}  // namespace

TEST_CASE("an object taken away is back in service after a while", "[home]") {
  const std::vector<repair::ExogenousEvent> failure{
      repair::becomes_unavailable(100.0, "glass1"), repair::becomes_unavailable(100.0, "glass2"),
      repair::object_appears(0.0, {"mug_new1", "mug", "kitchen", 1.0})};
  const std::vector<repair::ExogenousEvent> back = ObjectReturns(pddl::Problem{}, 1800.0).after_failure(failure);
  REQUIRE(back.size() == 2);
  CHECK(has(back, 1900.0, {"available", "glass1"}, true));
  CHECK(has(back, 1900.0, {"available", "glass2"}, true));
}

TEST_CASE("a remedy handed to a senior is collected, emptied and put back in its first room", "[home]") {
  const pddl::ProblemParseResult home = pddl::parse_problem(
      "(define (problem h) (:domain d) (:objects glass1 radio1 - thing s1 s2 - senior kitchen lounge - room)"
      " (:init (be glass1 kitchen) (be radio1 lounge)) (:goal (and)))",
      "home");
  REQUIRE(home.ast);
  repair::WorldState world;
  world.set({"given", "glass1", "s1"}, true);
  world.set({"filled", "glass1"}, true);
  world.set({"given", "radio1", "s2"}, true);
  ObjectReturns returns(*home.ast, 600.0);
  const std::vector<repair::ExogenousEvent> back = returns.collect_from(world, "s1", 500.0);
  REQUIRE(back.size() == 4);
  CHECK(has(back, 1100.0, {"given", "glass1", "s1"}, false));
  CHECK(has(back, 1100.0, {"filled", "glass1"}, false));
  CHECK(has(back, 1100.0, {"available", "glass1"}, true));
  CHECK(has(back, 1100.0, {"be", "glass1", "kitchen"}, true));
  // Another senior's remedy stays with them.
  CHECK(returns.collect_from(world, "s3", 500.0).empty());
  // Already on its way back: not collected twice (it could come back again
  // while given to someone else); once back and given anew, it is.
  CHECK(returns.collect_from(world, "s1", 800.0).empty());
  CHECK(returns.collect_from(world, "s1", 1200.0).size() == 4);
}

}  // namespace alplan::home
