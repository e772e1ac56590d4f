// The plan-stability testbed on an IPC domain it did not design: each
// perturbation breaks the rest of the plan (the testbed validates that), the
// strategies' plans are validated from the perturbed state, and the
// distance's parts add up.
#include "benchmarks/harness/stability_bench.h"

#include <catch2/catch.hpp>

#include <set>

#include "tests/support/test_paths.h"

using namespace alplan;

namespace {

bench::StabilityBenchOptions rovers_one() {
  bench::StabilityBenchOptions o;
  o.ipc_dir = test::benchmarks_dir() + "/ipc";
  o.domains = {"ipc-2002/rovers-time-automatic"};
  o.first_problem = o.last_problem = 1;
  o.perturbations = 1;
  o.strategies = {"replan", "patch"};
  o.plan_seconds = 10.0;
  o.strategy.planner.time_limit = 10.0;
  return o;
}

}  // namespace

TEST_CASE("bench stability: a perturbation breaks rovers' plan and replan mends it validly",
          "[stability]") {
  const bench::StabilityBenchOptions o = rovers_one();
  const bench::StabilityBenchResult result = bench::run_stability_bench(o);
  std::set<std::string> kinds;
  for (const bench::StabilityRun& r : result.runs) {
    kinds.insert(r.kind);
    CHECK(r.old_remaining > 0);
    if (r.strategy == "replan") CHECK(r.valid);
    if (!r.valid) continue;
    CHECK(r.distance == r.added + r.removed);
    CHECK(r.new_steps + r.removed == r.old_remaining + r.added);
    CHECK(r.makespan >= r.cut);
  }
  // Losing a thing rarely leaves rovers' goals reachable (one camera, one
  // rover): such a draw is passed over, and the skip says why.
  CHECK(kinds.count("fact"));
  CHECK(kinds.count("goal"));
  CHECK(result.runs.size() + 2 * result.skipped.size() == 6);
  for (const std::string& s : result.skipped) CHECK(s.find("left the goal reachable") != std::string::npos);
  const std::string summary = bench::stability_summary(result, o);
  CHECK(summary.find("## rovers-time-automatic") != std::string::npos);
  CHECK(summary.find("### Against replan") != std::string::npos);
}

TEST_CASE("bench stability: a perturbation is drawn against what the plan still needs", "[stability]") {
  bench::StabilityBenchOptions o = rovers_one();
  o.strategies = {"replan"};
  o.kinds = {bench::PerturbationKind::Goal};
  const bench::StabilityBenchResult result = bench::run_stability_bench(o);
  REQUIRE(result.runs.size() == 1);
  const bench::StabilityRun& r = result.runs.front();
  CHECK(r.description.find("goal (") == 0);
  // The new goal is something more to do: the old plan's rest lacks it, so
  // the repaired plan adds steps.
  CHECK(r.added > 0);
}
