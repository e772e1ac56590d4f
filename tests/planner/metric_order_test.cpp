// Weighted A* ordered by the metric (PlannerOptions::order): on tasks where
// the plan with fewest steps is not the best by the metric, the metric order
// finds the better plan first and the step order the worse one.
#include <catch2/catch.hpp>

#include "planner/grounder.h"
#include "planner/linear_metric.h"
#include "planner/planner.h"
#include "tests/support/task_loader.h"

using namespace alplan;
using Status = PlannerResult::Status;

namespace {

std::shared_ptr<const GroundTask> ground_text(const std::string& domain, const std::string& problem) {
  return ground(test::load_task_text(domain, problem).normalized);
}

// First plan of weighted A* (w=3) alone, no anytime improvement.
PlannerResult first_plan(const std::shared_ptr<const GroundTask>& task, const std::string& order) {
  PlannerOptions options;
  options.search = parse_search_configuration("wastar(trpg, w=3, order=" + order + ")");
  options.time_limit = 20.0;
  return Planner(task, options).plan();
}

// One step reaches the goal for 10; two steps reach it for 2. Preparing
// rules the express out, so the relaxation from there sees the cheap finish.
const char* kErrand = R"(
(define (domain errand) (:requirements :strips :numeric-fluents)
  (:predicates (undecided) (ready) (done))
  (:functions (total-cost))
  (:action express :parameters () :precondition (undecided)
    :effect (and (done) (increase (total-cost) 10)))
  (:action prepare :parameters () :precondition (undecided)
    :effect (and (ready) (not (undecided)) (increase (total-cost) 1)))
  (:action finish :parameters () :precondition (ready)
    :effect (and (done) (increase (total-cost) 1))))
)";
std::string errand_problem(const std::string& metric) {
  return "(define (problem p) (:domain errand) (:init (undecided) (= (total-cost) 0)) (:goal (done)) (:metric " +
         metric + "))";
}

// One long action (10) against two short concurrent ones and a join (about
// 3). The long one takes the robot's idleness while it runs, so after its
// start the relaxation sees a single step left: counting steps prefers it.
const char* kDetour = R"(
(define (domain detour) (:requirements :durative-actions)
  (:predicates (idle) (a) (b) (done))
  (:durative-action slow :parameters () :duration (= ?duration 10)
    :condition (at start (idle))
    :effect (and (at start (not (idle))) (at end (idle)) (at end (done))))
  (:durative-action part-a :parameters () :duration (= ?duration 2)
    :condition (at start (idle)) :effect (at end (a)))
  (:durative-action part-b :parameters () :duration (= ?duration 2)
    :condition (at start (idle)) :effect (at end (b)))
  (:durative-action join :parameters () :duration (= ?duration 1)
    :condition (and (at start (a)) (at start (b))) :effect (at end (done))))
)";
const char* kDetourProblem = R"(
(define (problem p) (:domain detour) (:init (idle)) (:goal (done)) (:metric minimize (total-time)))
)";

}  // namespace

TEST_CASE("metric order: weighted A* finds the cheap two-step plan, step order the costly one-step plan") {
  auto task = ground_text(kErrand, errand_problem("minimize (total-cost)"));
  const PlannerResult metric = first_plan(task, "metric");
  const PlannerResult steps = first_plan(task, "steps");
  REQUIRE(metric.status == Status::Solved);
  REQUIRE(steps.status == Status::Solved);
  CHECK(metric.best()->validation.value == Approx(2.0));
  CHECK(metric.best()->plan.steps.size() == 2);
  CHECK(metric.best()->engine.find("metric") != std::string::npos);
  CHECK(steps.best()->validation.value == Approx(10.0));
  CHECK(steps.best()->plan.steps.size() == 1);
}

TEST_CASE("metric order: weighted A* finds the short concurrent plan, step order the long single action") {
  auto task = ground_text(kDetour, kDetourProblem);
  const PlannerResult metric = first_plan(task, "metric");
  const PlannerResult steps = first_plan(task, "steps");
  REQUIRE(metric.status == Status::Solved);
  REQUIRE(steps.status == Status::Solved);
  CHECK(metric.best()->validation.value < 4.0);
  for (const PlanStep& step : metric.best()->plan.steps) CHECK(step.action != "slow");
  CHECK(steps.best()->validation.value == Approx(10.0));
  CHECK(steps.best()->plan.steps.size() == 1);
}

TEST_CASE("metric order: a metric that is not minimised and monotone keeps the step order") {
  auto task = ground_text(kErrand, errand_problem("maximize (total-cost)"));
  const PlannerResult metric = first_plan(task, "metric");
  REQUIRE(metric.status == Status::Solved);
  CHECK(metric.best()->plan.steps.size() == 1);
  CHECK(metric.best()->engine.find("metric") == std::string::npos);
}

TEST_CASE("metric order: an unknown order is refused") {
  // In the configuration, before any task is read (search_configuration.h).
  try {
    parse_search_configuration("wastar(trpg, order=cost)");
    FAIL("an unknown order was accepted");
  } catch (const SearchConfigurationError& e) {
    CHECK(std::string(e.what()).find("order is steps or metric") != std::string::npos);
  }
}

TEST_CASE("linear metric: weights of total-time and fluents, and what each action adds") {
  auto task = ground_text(kErrand, errand_problem("minimize (+ (* 2 (total-time)) (* (total-cost) 3))"));
  const std::optional<LinearMetric> metric = linear_metric(*task);
  REQUIRE(metric);
  CHECK(metric->time_weight == Approx(2.0));
  REQUIRE(metric->variables.size() == 1);
  CHECK(metric->variables[0].second == Approx(3.0));
  double express = 0, prepare = 0;
  for (std::size_t a = 0; a < task->actions.size(); ++a) {
    const std::string name = task->action_name(task->actions[a]);
    if (name.find("express") != std::string::npos) express = metric->start_cost[a];
    if (name.find("prepare") != std::string::npos) prepare = metric->start_cost[a];
  }
  CHECK(express == Approx(30.0));
  CHECK(prepare == Approx(3.0));
  SearchState state(static_cast<std::uint32_t>(task->facts.size()), task->initial_values);
  state.set_value(metric->variables[0].first, 4.0);
  CHECK(metric->value(state, 5.0) == Approx(2 * 5.0 + 3 * 4.0));
  CHECK(metric->remaining(6.0, 5.0, 7.5) == Approx(6.0 + 2 * 2.5));
  CHECK_FALSE(linear_metric(*ground_text(kErrand, errand_problem("minimize (- 0 (total-cost))"))));
}
