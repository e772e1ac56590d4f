// Required concurrency with bounded windows, as in temporal-machine-shop: a
// kiln is `ready` only while a firing runs, and a bake needs it over all.
// The partial plan orders a bake's end before the end of the firing that
// would break it as soon as the bake starts (so a bake too long for the
// firing fails at once); the relaxation gives `ready` for spans as long as
// a firing lasts and counts the firing long enough for each bake
// (planner/fact_windows.h, planner/partial_plan.h).
#include <catch2/catch.hpp>

#include <algorithm>

#include "planner/fact_windows.h"
#include "planner/grounder.h"
#include "planner/partial_plan.h"
#include "planner/planner.h"
#include "planner/task_index.h"
#include "planner/temporal_rpg.h"
#include "tests/support/ground_names.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

const char* const kKiln = R"(
(define (domain kiln) (:requirements :durative-actions)
  (:predicates (ready) (baked) (energy))
  (:durative-action fire-short :parameters () :duration (= ?duration 8)
    :condition (over all (energy))
    :effect (and (at start (ready)) (at end (not (ready)))))
  (:durative-action fire-long :parameters () :duration (= ?duration 20)
    :condition (over all (energy))
    :effect (and (at start (ready)) (at end (not (ready)))))
  (:durative-action bake :parameters () :duration (= ?duration 15)
    :condition (over all (ready))
    :effect (at end (baked))))
)";

std::shared_ptr<const GroundTask> kiln(bool with_long_firing) {
  std::string domain = kKiln;
  if (!with_long_firing) {
    const std::size_t from = domain.find("  (:durative-action fire-long");
    domain.erase(from, domain.find("  (:durative-action bake") - from);
  }
  return ground(test::load_task_text(domain, "(define (problem p) (:domain kiln) (:init (energy)) (:goal (baked)))")
                    .normalized);
}

StepRecord start_of(const GroundTask& task, const std::string& name, double duration) {
  StepRecord step;
  step.snap = {SnapKind::Start, test::action_named(task, name)};
  step.min_duration = step.max_duration = duration;
  return step;
}

HeuristicValue root_value(const std::shared_ptr<const GroundTask>& task) {
  const TaskIndex index(task);
  const PartialPlan plan(index, 0.001);
  SearchState state(static_cast<std::uint32_t>(task->facts.size()), task->initial_values);
  for (FactId f : task->initial_facts) state.set_fact(f, true);
  TemporalRpg rpg(index, TemporalRpgOptions{});
  return rpg.evaluate(state, plan);
}

}  // namespace

TEST_CASE("A bake longer than the firing it started in is unschedulable at its start", "[required-concurrency]") {
  const auto task = kiln(true);
  const TaskIndex index(task);
  PartialPlan short_firing(index, 0.001);
  REQUIRE(short_firing.append(start_of(*task, "(fire-short)", 8)));
  CHECK_FALSE(short_firing.append(start_of(*task, "(bake)", 15)));

  PartialPlan long_firing(index, 0.001);
  REQUIRE(long_firing.append(start_of(*task, "(fire-long)", 20)));
  REQUIRE(long_firing.append(start_of(*task, "(bake)", 15)));
  // The firing's end now waits for the bake's end: its latest is fixed by
  // its duration, its earliest is after the bake. The bake holds the
  // firing's fact over all, so it may start with the firing (VAL checks an
  // invariant after its start's happening): it ends at 15.
  CHECK(long_firing.pending_end_time(test::action_named(*task, "(fire-long)")) == Approx(20.0));
  CHECK(long_firing.pending_end_time(test::action_named(*task, "(bake)")) == Approx(15.0));
}

TEST_CASE("A fact only firings give is windowed, and the relaxation counts the firing long enough for the bake",
          "[required-concurrency]") {
  const auto task = kiln(true);
  const FactWindows windows(*task);
  CHECK(windows.windowed(test::fact_named(*task, "(ready)")));
  CHECK_FALSE(windows.windowed(test::fact_named(*task, "(baked)")));
  CHECK(windows.provider_span(test::action_named(*task, "(fire-long)")) == 20.0);

  const HeuristicValue value = root_value(task);
  REQUIRE_FALSE(value.dead_end());
  const Snap long_start{SnapKind::Start, test::action_named(*task, "(fire-long)")};
  const Snap short_start{SnapKind::Start, test::action_named(*task, "(fire-short)")};
  CHECK(std::count(value.helpful.begin(), value.helpful.end(), long_start) == 1);
  CHECK(std::count(value.helpful.begin(), value.helpful.end(), short_start) == 0);
}

TEST_CASE("With only a firing too short for the bake the relaxation sees the dead end, and the planner proves it",
          "[required-concurrency]") {
  const auto task = kiln(false);
  CHECK(root_value(task).dead_end());
  PlannerOptions options;
  options.time_limit = 10.0;
  const PlannerResult result = Planner(task, options).plan();
  CHECK(result.status == PlannerResult::Status::Unsolvable);
}

TEST_CASE("The planner bakes inside the long firing", "[required-concurrency]") {
  PlannerOptions options;
  options.time_limit = 10.0;
  const PlannerResult result = Planner(kiln(true), options).plan();
  REQUIRE(result.status == PlannerResult::Status::Solved);
  CHECK(result.best()->validation.valid);
  CHECK(result.best()->plan.steps.size() == 2);
}
