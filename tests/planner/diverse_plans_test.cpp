#include "planner/diverse_plans.h"

#include <catch2/catch.hpp>

#include "planner/grounder.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

// Any one of the cups serves: as many one-step plans as there are cups,
// each two of them 2 apart (one action out, one in).
const char* kCups = R"(
(define (domain cups) (:requirements :typing :durative-actions)
  (:types cup)
  (:predicates (available ?c - cup) (served))
  (:durative-action serve :parameters (?c - cup) :duration (= ?duration 5)
    :condition (at start (available ?c)) :effect (at end (served))))
)";
const char* kThreeCups = R"(
(define (problem three) (:domain cups) (:objects c1 c2 c3 - cup)
  (:init (available c1) (available c2) (available c3)) (:goal (served)))
)";

std::shared_ptr<const GroundTask> three_cups() {
  return ground(test::load_task_text(kCups, kThreeCups).normalized);
}

Plan plan_of(const std::vector<std::string>& names) {
  Plan plan;
  double t = 0.0;
  for (const std::string& n : names) {
    PlanStep step;
    step.time = t;
    step.action = n;
    step.args = {"x"};
    plan.steps.push_back(step);
    t += 1.0;
  }
  return plan;
}

DiversePlanOptions asking(std::size_t k, std::size_t d) {
  DiversePlanOptions o;
  o.k = k;
  o.min_distance = d;
  o.planner.time_limit = 10.0;
  return o;
}

}  // namespace

TEST_CASE("the action-set distance counts a multiset's actions out and in, times ignored") {
  CHECK(action_multiset_distance({}, {}) == 0);
  CHECK(action_multiset_distance({"(a)", "(b)"}, {"(b)", "(a)"}) == 0);
  CHECK(action_multiset_distance({"(a)", "(a)", "(b)"}, {"(a)", "(c)"}) == 3);
  CHECK(action_multiset_distance({"(a)"}, {}) == 1);
  const Plan ab = plan_of({"a", "b"});
  Plan later = ab;
  for (PlanStep& s : later.steps) *s.time += 7.0;
  CHECK(plan_action_distance(ab, later) == 0);
  CHECK(plan_action_distance(ab, plan_of({"a", "c", "d"})) == 3);
  CHECK(plan_step_name(ab.steps[0]) == "(a x)");
}

TEST_CASE("three cups give three plans, each pair 2 apart and each valid") {
  const DiversePlans found = find_diverse_plans(three_cups(), asking(3, 2));
  REQUIRE(found.plans.size() == 3);
  for (std::size_t i = 0; i < found.plans.size(); ++i) {
    CHECK(found.plans[i].validation.valid);
    REQUIRE(found.plans[i].plan.steps.size() == 1);
    for (std::size_t j = i + 1; j < found.plans.size(); ++j) {
      CHECK(plan_action_distance(found.plans[i].plan, found.plans[j].plan) >= 2);
    }
  }
  CHECK(found.first_status == PlannerResult::Status::Solved);
}

TEST_CASE("asking for more plans than the method finds returns those it found, the search exhausted") {
  const DiversePlans found = find_diverse_plans(three_cups(), asking(5, 2));
  CHECK(found.plans.size() == 3);
  CHECK(found.exhausted);
  // No two one-cup plans are 3 apart: only the first plan is kept.
  const DiversePlans far = find_diverse_plans(three_cups(), asking(3, 3));
  CHECK(far.plans.size() == 1);
  CHECK(far.exhausted);
}

TEST_CASE("the same options give the same plans") {
  DiversePlanOptions o = asking(3, 2);
  o.seed = 7;
  const DiversePlans a = find_diverse_plans(three_cups(), o);
  const DiversePlans b = find_diverse_plans(three_cups(), o);
  REQUIRE(a.plans.size() == b.plans.size());
  for (std::size_t i = 0; i < a.plans.size(); ++i) CHECK(a.plans[i].text == b.plans[i].text);
}

TEST_CASE("a task without a plan gives none, with the first search's status") {
  const char* none = R"(
(define (problem none) (:domain cups) (:objects c1 - cup) (:init) (:goal (served)))
)";
  const DiversePlans found = find_diverse_plans(ground(test::load_task_text(kCups, none).normalized), asking(3, 2));
  CHECK(found.plans.empty());
  CHECK(found.first_status == PlannerResult::Status::Unsolvable);
  CHECK(found.planner_calls == 1);
}
