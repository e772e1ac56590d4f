// How much room the partial plan leaves the actions still running: the
// latest time each end can come (PartialPlan::latest_end_times), which the
// relaxation's fact windows and the search's dominance test read.
#include "planner/partial_plan.h"

#include <catch2/catch.hpp>
#include <limits>

#include "planner/grounder.h"
#include "tests/support/ground_names.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

const char* const kShop = R"(
(define (domain shop) (:requirements :durative-actions)
  (:predicates (open) (baked) (fired))
  (:durative-action fire :parameters () :duration (<= ?duration 10)
    :effect (and (at start (open)) (at end (not (open))) (at end (fired))))
  (:durative-action bake :parameters () :duration (= ?duration 3)
    :condition (over all (open))
    :effect (at end (baked))))
)";

std::shared_ptr<const GroundTask> shop() {
  return ground(test::load_task_text(kShop, "(define (problem p) (:domain shop) (:goal (and (baked) (fired))))")
                    .normalized);
}

RunningAction running_since_before(ActionId action, double min, double max) {
  RunningAction r;
  r.action = action;
  r.min_duration = min;
  r.max_duration = max;
  return r;
}

}  // namespace

TEST_CASE("an action running since before the plan may end no later than its longest duration") {
  const auto task = shop();
  const TaskIndex index(task);
  const ActionId fire = test::action_named(*task, "(fire)");
  const ActionId bake = test::action_named(*task, "(bake)");
  const std::vector<RunningAction> running{running_since_before(fire, 0.0, 10.0),
                                           running_since_before(bake, 3.0, 3.0)};
  const PartialPlan plan(index, 0.001, 0.0, running);
  const std::vector<double> latest = plan.latest_end_times(running);
  REQUIRE(latest.size() == 2);
  CHECK(latest[0] == Approx(10.0));
  CHECK(latest[1] == Approx(3.0));
}

TEST_CASE("an unbounded running action has infinite room, an action not running has none to report") {
  const auto task = shop();
  const TaskIndex index(task);
  const ActionId fire = test::action_named(*task, "(fire)");
  const ActionId bake = test::action_named(*task, "(bake)");
  const std::vector<RunningAction> running{running_since_before(fire, 0.0, kInfiniteDuration)};
  const PartialPlan plan(index, 0.001, 0.0, running);
  const std::vector<RunningAction> asked{running.front(), running_since_before(bake, 3.0, 3.0)};
  const std::vector<double> latest = plan.latest_end_times(asked);
  REQUIRE(latest.size() == 2);
  CHECK(latest[0] == std::numeric_limits<double>::infinity());
  CHECK(latest[1] == std::numeric_limits<double>::infinity());
}

TEST_CASE("a step started while an action runs leaves that action's end its full room") {
  // bake needs `open`, which fire's end deletes: whatever bake's start adds
  // to the network orders nothing after fire's end, so fire may end at 10.
  const auto task = shop();
  const TaskIndex index(task);
  const ActionId fire = test::action_named(*task, "(fire)");
  const std::vector<RunningAction> running{running_since_before(fire, 1.0, 10.0)};
  PartialPlan plan(index, 0.001, 0.0, running);
  REQUIRE(plan.append({{SnapKind::Start, test::action_named(*task, "(bake)")}, kNoId, 3.0, 3.0}));
  CHECK(plan.latest_end_times(running).front() == Approx(10.0));
}

// VAL counts a conditional effect's condition as read only where it holds
// before the happening (the differential tester's tasks 4294974730 and
// 8589936741): a snap none of whose conditional effects fired is ordered by
// its quiet footprint, which lets a later writer of the condition share its
// happening but keeps an earlier one epsilon before it (the search
// evaluates the condition where the snap stands).
TEST_CASE("a conditional effect that did not fire lets later writers of its condition share the happening") {
  const char* const domain = R"(
(define (domain quiet) (:requirements :strips :conditional-effects)
  (:predicates (p) (q) (r))
  (:action check :parameters () :precondition (and) :effect (and (r) (when (p) (q))))
  (:action set-p :parameters () :precondition (and) :effect (p)))
)";
  const auto task = ground(test::load_task_text(domain, "(define (problem q) (:domain quiet) (:goal (q)))").normalized);
  const TaskIndex index(task);
  const Snap check{SnapKind::Instant, test::action_named(*task, "(check)")};
  const Snap set_p{SnapKind::Instant, test::action_named(*task, "(set-p)")};
  auto makespan = [&](StepRecord first, StepRecord second) {
    PartialPlan plan(index, 0.001);
    REQUIRE(plan.append(first));
    REQUIRE(plan.append(second));
    return plan.makespan();
  };
  StepRecord quiet_check{check};
  quiet_check.quiet = true;
  CHECK(makespan(quiet_check, StepRecord{set_p}) == Approx(0.0));
  CHECK(makespan(StepRecord{check}, StepRecord{set_p}) == Approx(0.001));  // fired: read
  CHECK(makespan(StepRecord{set_p}, quiet_check) == Approx(0.001));         // written before it
}
