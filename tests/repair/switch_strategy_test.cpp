// switch (repair/switch_strategy.cpp): an alternative kept for the goal
// replaces the failed plan without search; with none executable, replan.
#include <catch2/catch.hpp>

#include <algorithm>

#include "planner/grounder.h"
#include "planner/planner.h"
#include "repair/executing_plan.h"
#include "repair/repair_strategy.h"
#include "repair/world_simulator.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

// The robot walks to the kitchen, takes one of two cups there and serves.
const char* kCafe = R"(
(define (domain cafe) (:requirements :typing :durative-actions)
  (:types cup room)
  (:predicates (available ?c - cup) (cup-at ?c - cup ?r - room) (robot-at ?r - room) (holding ?c - cup)
               (connected ?a ?b - room) (served))
  (:durative-action move :parameters (?a ?b - room) :duration (= ?duration 10)
    :condition (and (at start (robot-at ?a)) (at start (connected ?a ?b)))
    :effect (and (at start (not (robot-at ?a))) (at end (robot-at ?b))))
  (:durative-action take :parameters (?c - cup ?r - room) :duration (= ?duration 2)
    :condition (and (at start (robot-at ?r)) (at start (cup-at ?c ?r)) (at start (available ?c)))
    :effect (and (at start (not (cup-at ?c ?r))) (at end (holding ?c))))
  (:durative-action serve :parameters (?c - cup) :duration (= ?duration 3)
    :condition (at start (holding ?c)) :effect (at end (served))))
)";
const char* kCafeProblem = R"(
(define (problem cafe1) (:domain cafe) (:objects c1 c2 - cup home kitchen - room)
  (:init (robot-at home) (connected home kitchen) (connected kitchen home)
         (cup-at c1 kitchen) (cup-at c2 kitchen) (available c1) (available c2))
  (:goal (served)) (:metric minimize (total-time)))
)";

struct Cafe {
  test::LoadedTask loaded = test::load_task_text(kCafe, kCafeProblem);
  repair::ExecutingPlan plan;
  Violation failure;
  std::string cup;  // the cup the plan takes

  Cafe() {
    const std::shared_ptr<const GroundTask> task = ground(loaded.normalized);
    const PlannerResult planned = Planner(task, repair::executing_planner_options()).plan();
    REQUIRE(planned.best());
    plan = repair::bind_plan(task, planned.best()->plan, 0.001);
    REQUIRE(plan.steps.size() == 3);
    cup = plan.steps[1].name.substr(6, 2);  // "(take cX kitchen)"
    failure.kind = Violation::Kind::UnsatisfiedPrecondition;
    failure.time = plan.steps[1].start;
    failure.condition = "(available " + cup + ")";
    failure.action = plan.steps[1].name + " - start";
  }

  // At the take, in the kitchen, with the given cups no longer available.
  repair::RepairRequest request(const std::vector<std::string>& gone) const {
    repair::RepairRequest r;
    r.domain = loaded.domain.get();
    r.problem = loaded.problem.get();
    r.plan = &plan;
    r.failure = &failure;
    r.now = plan.steps[1].start;
    r.observed = repair::initial_world(*loaded.problem);
    r.observed.set({"robot-at", "home"}, false);
    r.observed.set({"robot-at", "kitchen"}, true);
    for (const std::string& c : gone) r.observed.set({"available", c}, false);
    r.observed.time = r.now;
    r.robot_location = "kitchen";
    return r;
  }
};

}  // namespace

TEST_CASE("switch takes the alternative with the other cup, and searches no more once it keeps the set") {
  const Cafe cafe;
  const std::string other = cafe.cup == "c1" ? "c2" : "c1";
  const std::unique_ptr<repair::RepairStrategy> strategy = repair::make_strategy("switch", {});
  CHECK(strategy->name() == "switch");
  const repair::RepairResult first = strategy->repair(cafe.request({cafe.cup}));
  REQUIRE(first.repaired);
  CHECK(first.fallback.empty());
  CHECK(first.how.find("switched to alternative") == 0);
  CHECK(first.planner_calls > 0);  // the first repair of the goal plans the alternatives
  REQUIRE(first.plan->steps.size() == 2);
  CHECK(first.plan->steps[0].name == "(take " + other + " kitchen)");
  CHECK(first.plan->steps[0].start >= cafe.plan.steps[1].start - 1e-9);
  CHECK(repair::validate_from_now(*first.plan, cafe.plan.steps[1].start).valid);

  const repair::RepairResult again = strategy->repair(cafe.request({cafe.cup}));
  REQUIRE(again.repaired);
  CHECK(again.planner_calls == 0);
  CHECK(again.how.find("without search") != std::string::npos);
  CHECK(again.plan->steps[0].name == first.plan->steps[0].name);
}

TEST_CASE("switch replans when no alternative it keeps is executable, and says so") {
  const Cafe cafe;
  repair::StrategyOptions options;
  options.switch_plans = 1;  // only the plan that failed
  const std::unique_ptr<repair::RepairStrategy> strategy = repair::make_strategy("switch", options);
  const repair::RepairResult result = strategy->repair(cafe.request({cafe.cup}));
  REQUIRE(result.repaired);
  CHECK(result.fallback == "replan");
  CHECK(result.how.find("none of the 1 diverse plans") == 0);
  CHECK(result.planner_calls == 2);  // the alternative, then the replan
}

TEST_CASE("switch without any cup left finds no repair") {
  const Cafe cafe;
  const std::unique_ptr<repair::RepairStrategy> strategy = repair::make_strategy("switch", {});
  const repair::RepairResult result = strategy->repair(cafe.request({"c1", "c2"}));
  CHECK_FALSE(result.repaired);
  CHECK(result.fallback == "replan");
}

TEST_CASE("switch is one of the strategies") {
  const std::vector<std::string> names = repair::strategy_names();
  CHECK(std::find(names.begin(), names.end(), "switch") != names.end());
}
