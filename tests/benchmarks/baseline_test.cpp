#include "benchmarks/harness/baseline.h"

#include <catch2/catch.hpp>

#include "benchmarks/harness/suite.h"
#include "tests/support/test_paths.h"

using namespace alplan::bench;

TEST_CASE("the PDDL 3 baseline reads OPTIC's two runs and counts either valid plan") {
  const Baseline b = Baseline::load(alplan::test::benchmarks_dir() + "/pddl3/baseline");
  REQUIRE(b.planners == std::vector<std::string>{"optic-first", "optic-anytime", "optic-either"});
  CHECK(b.runs.size() == 45);
  int either = 0, first = 0, anytime = 0;
  for (const auto& [problem, runs] : b.runs) {
    first += runs.at("optic-first").valid;
    anytime += runs.at("optic-anytime").valid;
    either += runs.at("optic-either").valid;
  }
  // The baseline README: a valid plan on 18 of 45 in either run.
  CHECK(either == 18);
  CHECK(first == 18);
  CHECK(anytime == 16);
  const std::string trucks = "pddl3/ipc-2006/trucks-preferences-complex/instances/instance-1.pddl";
  REQUIRE(b.runs.count(trucks));
  CHECK(b.runs.at(trucks).at("optic-first").value == 9.0);
  CHECK(b.runs.at(trucks).at("optic-either").value == 1.0);  // the anytime run's better plan
  CHECK(b.best.at(trucks) == 1.0);
  // pipesworld's preferences are maximised: the larger value is the better.
  const std::string pipes = "pddl3/ipc-2006/pipesworld-preferences-complex/instances/instance-5.pddl";
  CHECK(b.maximized(pipes));
  CHECK_FALSE(b.maximized(trucks));
  CHECK(b.best.at(pipes) == 48.0);
  // The suite's keys are the baseline's.
  int found = 0;
  for (const SuiteProblem& p : load_suite(alplan::test::benchmarks_dir() + "/pddl3")) found += b.runs.count(problem_key(p.problem_file));
  CHECK(found == 45);
}

TEST_CASE("quality is best over ours when minimised, ours over best when maximised, and 0 against 0 exact") {
  CHECK(quality_score(4.0, 2.0, false) == 0.5);
  CHECK(quality_score(2.0, 4.0, true) == 0.5);
  CHECK(quality_score(0.0, 0.0, false) == 1.0);
  CHECK(quality_score(3.0, 0.0, false) == 0.0);
  CHECK(quality_score(0.0, 0.0, true) == 1.0);
}
