// PDDL 3 in the validator, on a small domain of lights: each modal operator
// as a hard constraint (a plan that keeps it, one that breaks it, and the
// boundaries VAL draws), preference counting (per forall instance, once for a
// forall inside the preference, per action occurrence for a precondition
// preference, per goal instance), is-violated in the metric, and the
// planner's refusal naming the construct and its place.
#include <catch2/catch.hpp>

#include "planner/grounder.h"
#include "planner/planner.h"
#include "planner/validator.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

const char* kDomain = R"(
(define (domain lights)
  (:requirements :typing :durative-actions :negative-preconditions :constraints :preferences)
  (:types light)
  (:predicates (lit ?l - light) (broken ?l - light))
  (:durative-action on
    :parameters (?l - light)
    :duration (= ?duration 1)
    :condition (and (at start (not (lit ?l))) (preference fresh (at start (not (broken ?l)))))
    :effect (at end (lit ?l)))
  (:durative-action off
    :parameters (?l - light)
    :duration (= ?duration 1)
    :condition (at start (lit ?l))
    :effect (at end (not (lit ?l))))
  (:action smash
    :parameters (?l - light)
    :precondition (preference careful (not (lit ?l)))
    :effect (broken ?l)))
)";

std::string problem(const std::string& constraints, const std::string& goal = "(and)",
                    const std::string& metric = "") {
  return "(define (problem p) (:domain lights) (:objects a b - light) (:init) (:goal " + goal + ")" +
         (constraints.empty() ? "" : " (:constraints " + constraints + ")") +
         (metric.empty() ? "" : " (:metric minimize " + metric + ")") + ")";
}

ValidationResult check(const std::string& problem_text, const std::string& plan_text) {
  const test::LoadedTask task = test::load_task_text(kDomain, problem_text);
  PlanValidator validator(task.normalized);
  const PlanReadResult plan = read_plan(plan_text, "plan");
  REQUIRE(plan.ok());
  return validator.validate(plan.plan);
}

bool valid(const std::string& constraints, const std::string& plan_text) {
  const ValidationResult r = check(problem(constraints), plan_text);
  INFO((r.valid ? std::string("valid") : r.violation->message()));
  if (!r.valid) CHECK(r.violation->kind == Violation::Kind::ConstraintViolated);
  return r.valid;
}

// The metric's value for a plan, the metric reading is-violated.
double value(const std::string& constraints, const std::string& plan_text, const std::string& metric,
             const std::string& goal = "(and)") {
  const ValidationResult r = check(problem(constraints, goal, metric), plan_text);
  INFO((r.valid ? std::string("valid") : r.violation->message()));
  REQUIRE(r.valid);
  return r.value;
}

}  // namespace

TEST_CASE("always and at end are checked in every state and in the final one") {
  CHECK(valid("(always (not (broken a)))", "0: (on a) [1]\n"));
  CHECK_FALSE(valid("(always (not (broken a)))", "0: (on a) [1]\n2: (smash b)\n3: (smash a)\n"));
  CHECK(valid("(at end (lit a))", "0: (on a) [1]\n"));
  CHECK_FALSE(valid("(at end (lit a))", "0: (on a) [1]\n2: (off a) [1]\n"));
  // The initial state is a state of the trajectory too.
  CHECK_FALSE(valid("(always (lit a))", "0: (on a) [1]\n"));
}

TEST_CASE("sometime and within: within t counts from the plan's start, t itself included") {
  CHECK(valid("(sometime (lit b))", "0: (on b) [1]\n"));
  CHECK_FALSE(valid("(sometime (lit b))", "0: (on a) [1]\n"));
  CHECK(valid("(within 1 (lit a))", "0: (on a) [1]\n"));
  CHECK_FALSE(valid("(within 1 (lit a))", "0.5: (on a) [1]\n"));
  // Never reached at all: violated at the end.
  CHECK_FALSE(valid("(within 10 (lit b))", "0: (on a) [1]\n"));
}

TEST_CASE("at-most-once: true, false and true again is a violation") {
  CHECK(valid("(at-most-once (lit a))", "0: (on a) [1]\n2: (off a) [1]\n"));
  CHECK_FALSE(valid("(at-most-once (lit a))", "0: (on a) [1]\n2: (off a) [1]\n4: (on a) [1]\n"));
}

TEST_CASE("sometime-after and sometime-before") {
  CHECK(valid("(sometime-after (lit a) (lit b))", "0: (on a) [1]\n2: (on b) [1]\n"));
  CHECK_FALSE(valid("(sometime-after (lit a) (lit b))", "0: (on a) [1]\n"));
  // The obligation is met by the state that triggers it.
  CHECK(valid("(sometime-after (lit a) (lit b))", "0: (on a) [1]\n0: (on b) [1]\n"));
  // Never triggered: nothing is owed.
  CHECK(valid("(sometime-after (lit a) (lit b))", "0: (on b) [1]\n"));
  CHECK(valid("(sometime-before (lit a) (lit b))", "0: (on b) [1]\n2: (on a) [1]\n"));
  CHECK_FALSE(valid("(sometime-before (lit a) (lit b))", "0: (on a) [1]\n"));
  // Strictly before: b becoming true in the same state as a is too late.
  CHECK_FALSE(valid("(sometime-before (lit a) (lit b))", "0: (on a) [1]\n0: (on b) [1]\n"));
}

TEST_CASE("always-within: each trigger opens a deadline of its own") {
  CHECK(valid("(always-within 2 (lit a) (lit b))", "0: (on a) [1]\n1.5: (on b) [1]\n"));
  CHECK_FALSE(valid("(always-within 2 (lit a) (lit b))", "0: (on a) [1]\n3: (on b) [1]\n"));
  CHECK_FALSE(valid("(always-within 2 (lit a) (lit b))", "0: (on a) [1]\n"));
  CHECK(valid("(always-within 2 (lit a) (lit b))", "0: (on b) [1]\n"));
}

TEST_CASE("hold-during and hold-after") {
  CHECK(valid("(hold-during 2 4 (lit a))", "0: (on a) [1]\n"));
  CHECK_FALSE(valid("(hold-during 2 4 (lit a))", "0: (on a) [1]\n2: (off a) [1]\n"));
  // The window is half-open: a state at t2 is outside it.
  CHECK(valid("(hold-during 2 4 (lit a))", "0: (on a) [1]\n3: (off a) [1]\n"));
  CHECK(valid("(hold-after 2 (lit a))", "0: (on a) [1]\n"));
  CHECK_FALSE(valid("(hold-after 2 (lit a))", "0: (on a) [1]\n3: (off a) [1]\n"));
}

TEST_CASE("constraints under forall and and hold for every instance") {
  CHECK(valid("(and (forall (?l - light) (sometime (lit ?l))))", "0: (on a) [1]\n0: (on b) [1]\n"));
  CHECK_FALSE(valid("(and (forall (?l - light) (sometime (lit ?l))))", "0: (on a) [1]\n"));
}

TEST_CASE("a preference under forall counts per instance, a forall inside it once") {
  const std::string per_instance = "(forall (?l - light) (preference p (sometime (lit ?l))))";
  CHECK(value(per_instance, "", "(is-violated p)") == 2);
  CHECK(value(per_instance, "0: (on a) [1]\n", "(is-violated p)") == 1);
  const std::string shared = "(preference p (forall (?l - light) (sometime (lit ?l))))";
  CHECK(value(shared, "", "(is-violated p)") == 1);
  CHECK(value(shared, "0: (on a) [1]\n0: (on b) [1]\n", "(is-violated p)") == 0);
  // Violated in many states, counted once.
  CHECK(value("(preference q (always (lit a)))", "5: (on b) [1]\n", "(is-violated q)") == 1);
}

TEST_CASE("precondition preferences count per occurrence, goal preferences per instance") {
  // careful: smash only unlit lights; fresh: switch on only unbroken ones.
  const std::string metric = "(+ (* 10 (is-violated careful)) (is-violated fresh))";
  CHECK(value("", "0: (on a) [1]\n0: (on b) [1]\n2: (smash a)\n3: (smash b)\n", metric) == 20);
  CHECK(value("", "0: (smash a)\n1: (on a) [1]\n", metric) == 1);
  const std::string goal = "(forall (?l - light) (preference g (lit ?l)))";
  CHECK(value("", "0: (on a) [1]\n", "(is-violated g)", goal) == 1);
  CHECK(value("", "", "(is-violated g)", goal) == 2);
  // A name no preference has counts 0, as in VAL.
  CHECK(value("", "", "(+ 3 (is-violated nowhere))") == 3);
}

TEST_CASE("the planner plans constraints and preferences the validator then counts") {
  const test::LoadedTask task = test::load_task_text(kDomain, problem("(sometime (lit a))"));
  const PlannerResult r = Planner(ground(task.normalized), {}).plan();
  INFO(r.message);
  REQUIRE(r.status == PlannerResult::Status::Solved);
  CHECK(r.best()->validation.valid);
  CHECK(r.best()->text.find("(on a)") != std::string::npos);
}
