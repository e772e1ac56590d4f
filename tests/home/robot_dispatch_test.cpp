#include "home/robot_dispatch.h"

#include <catch2/catch.hpp>

#include <algorithm>

#include "pddl_parser/parser.h"

namespace alplan::home {
namespace {

// A corridor c1 - c2 - c3 with a room off each end: r1 waits in room_a
// (next to c1), r2 in c2, r3 in room_b (next to c3); s1 lives in room_a,
// s2 in room_b.
pddl::Problem corridor_home() {
  std::string paths;
  const auto both = [&](const std::string& a, const std::string& b, int t) {
    paths += "(path " + a + " " + b + ") (path " + b + " " + a + ") (= (moving_time " + a + " " + b + ") " +
             std::to_string(t) + ") (= (moving_time " + b + " " + a + ") " + std::to_string(t) + ") ";
  };
  both("room_a", "c1", 10);
  both("c1", "c2", 50);
  both("c2", "c3", 50);
  both("c3", "room_b", 10);
  const std::string text =
      "(define (problem h) (:domain d) (:objects r1 r2 r3 - robot s1 s2 - senior room_a room_b c1 c2 c3 - room)"
      " (:init " + paths + "(be r1 room_a) (be r2 c2) (be r3 room_b) (be s1 room_a) (be s2 room_b)"
      " (holding r3 cup) (= (battery r3) 5))"
      " (:goal (and)))";
  pddl::ProblemParseResult parsed = pddl::parse_problem(text, "home");
  REQUIRE(parsed.ast);
  pddl::Problem problem = *parsed.ast;
  pddl::TimedInitialLiteral til;
  til.time = 100.0;
  til.atom.name = "be";
  til.atom.args = {pddl::Term{pddl::Term::Kind::Name, "r3", {}}, pddl::Term{pddl::Term::Kind::Name, "c3", {}}};
  problem.timed_literals.push_back(til);
  return problem;
}

const std::vector<std::string> kRobots{"r1", "r2", "r3"};

}  // namespace

TEST_CASE("each senior gets the nearest free robot, the most urgent first", "[home]") {
  const pddl::Problem home = corridor_home();
  CHECK(dispatch_robots(home, kRobots, {{"s2", 500.0}}) == std::vector<std::string>{"r3"});
  CHECK(dispatch_robots(home, kRobots, {{"s1", 500.0}, {"s2", 400.0}}) == std::vector<std::string>{"r3", "r1"});
  // A senior named twice is served once; more seniors than robots share them.
  CHECK(dispatch_robots(home, {"r2"}, {{"s1", 500.0}, {"s2", 400.0}, {"s2", 600.0}}) ==
        std::vector<std::string>{"r2"});
  // A robot nowhere to be seen is not sent.
  CHECK(dispatch_robots(home, {"r9"}, {{"s1", 500.0}}).empty());
}

TEST_CASE("the problem keeps only the dispatched robots", "[home]") {
  const pddl::Problem home = corridor_home();
  const pddl::Problem kept = with_robots_only(home, kRobots, {"r1"});
  const auto mentions = [](const pddl::Atom& a, const std::string& name) {
    return std::any_of(a.args.begin(), a.args.end(), [&](const pddl::Term& t) { return t.name == name; });
  };
  for (const std::string gone : {"r2", "r3"}) {
    CHECK(std::none_of(kept.objects.begin(), kept.objects.end(), [&](const pddl::TypedName& o) { return o.name == gone; }));
    CHECK(std::none_of(kept.init.begin(), kept.init.end(), [&](const pddl::Atom& a) { return mentions(a, gone); }));
    CHECK(std::none_of(kept.numeric_init.begin(), kept.numeric_init.end(),
                       [&](const pddl::NumericFact& f) { return mentions(f.function, gone); }));
  }
  CHECK(kept.timed_literals.empty());
  CHECK(std::any_of(kept.init.begin(), kept.init.end(), [&](const pddl::Atom& a) { return mentions(a, "r1"); }));
  // Rooms, paths and seniors stay.
  CHECK(kept.init.size() == home.init.size() - 3);
  CHECK(with_robots_only(home, kRobots, kRobots) == home);
}

}  // namespace alplan::home
