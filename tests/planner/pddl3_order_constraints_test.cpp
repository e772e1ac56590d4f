// The PDDL 3 operators that judge the order of states, planned (issue 44;
// planner/pddl3_order_constraints.h): each hard one holds in the plan the
// planner prints, by the validator, which judges it apart from the
// compilation; a task the constraint makes impossible gets no plan and no
// claim of proof; a preference of these operators is traded by the rounds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "planner/grounder.h"
#include "planner/pddl3_order_constraints.h"
#include "planner/planner.h"
#include "planner/search_configuration.h"
#include "planner/validator.h"
#include "tests/support/pddl3_planning.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

// A light that task-a and task-b need on throughout; task-b needs a reset
// first, which switching off gives, and so does `prepare`, after a key and
// a spare are fetched. The shortest plan by steps lights the lamp twice
// (on, a, off, on, b); the one through prepare lights it once.
const char* const kLight = R"(
(define (domain light) (:requirements :strips :durative-actions :negative-preconditions :constraints :preferences)
  (:predicates (on) (reset) (done-a) (done-b) (key) (spare))
  (:durative-action turn-on :parameters () :duration (= ?duration 1)
    :condition (at start (not (on))) :effect (at end (on)))
  (:durative-action turn-off :parameters () :duration (= ?duration 1)
    :condition (at start (on)) :effect (and (at end (not (on))) (at end (reset))))
  (:durative-action get-key :parameters () :duration (= ?duration 1) :effect (at end (key)))
  (:durative-action fetch-spare :parameters () :duration (= ?duration 1)
    :condition (at start (key)) :effect (at end (spare)))
  (:durative-action prepare :parameters () :duration (= ?duration 2)
    :condition (at start (spare)) :effect (at end (reset)))
  (:durative-action task-a :parameters () :duration (= ?duration 2)
    :condition (over all (on)) :effect (at end (done-a)))
  (:durative-action task-b :parameters () :duration (= ?duration 2)
    :condition (and (at start (reset)) (over all (on))) :effect (at end (done-b))))
)";

std::string problem(const std::string& goal, const std::string& constraints, const std::string& metric = "",
                    const std::string& init = "") {
  return "(define (problem p) (:domain light) (:init " + init + ") (:goal " + goal + ") (:constraints " +
         constraints + ")" + (metric.empty() ? "" : " (:metric " + metric + ")") + ")";
}

PlannerResult plan(const std::string& problem_text, PlannerOptions options = {}) {
  return test::plan_texts(kLight, problem_text, options);
}

// The printed plan is valid on the original task, constraints included.
ValidationResult check_valid(const std::string& problem_text, const PlannerResult& result) {
  return test::check_printed_plan_valid(kLight, problem_text, result);
}

std::size_t count_steps(const PlannerResult& result, const std::string& action) {
  std::size_t n = 0;
  const std::string step = "(" + action + ")";
  for (std::size_t at = result.best()->text.find(step); at != std::string::npos;
       at = result.best()->text.find(step, at + 1)) {
    ++n;
  }
  return n;
}

// Without the constraint the same goal is planned, and differently: the
// constraint is what changed the plan.
void check_constraint_changes_plan(const std::string& goal, const std::string& constraint, const std::string& action,
                                   std::size_t without, std::size_t with) {
  const PlannerResult free = plan(problem(goal, "(and)"));
  REQUIRE(free.status == PlannerResult::Status::Solved);
  CHECK(count_steps(free, action) == without);
  const std::string p = problem(goal, constraint);
  const PlannerResult constrained = plan(p);
  check_valid(p, constrained);
  CHECK(count_steps(constrained, action) == with);
}

}  // namespace

TEST_CASE("fact_disjunction reads a fact, a disjunction of facts, and refuses other forms") {
  ConditionSet one;
  one.positive = {3};
  CHECK(fact_disjunction(one) == std::optional<std::vector<FactId>>(std::vector<FactId>{3}));
  ConditionSet either;
  GroundFormula disjunction;
  disjunction.kind = GroundFormula::Kind::Or;
  for (FactId f : {7u, 2u}) {
    GroundFormula literal;
    literal.kind = GroundFormula::Kind::Literal;
    literal.fact = f;
    disjunction.children.push_back(literal);
  }
  either.complex = {disjunction};
  CHECK(fact_disjunction(either) == std::optional<std::vector<FactId>>(std::vector<FactId>{2, 7}));
  ConditionSet both;
  both.positive = {1, 2};
  CHECK_FALSE(fact_disjunction(both));
  ConditionSet negated;
  negated.negative = {1};
  CHECK_FALSE(fact_disjunction(negated));
  ConditionSet never;
  never.never = "false";
  CHECK(fact_disjunction(never) == std::optional<std::vector<FactId>>(std::vector<FactId>{}));
}

TEST_CASE("a hard at-most-once keeps the light from coming on twice") {
  check_constraint_changes_plan("(and (done-a) (done-b))", "(at-most-once (on))", "turn-on", 2, 1);
}

TEST_CASE("a hard at-most-once that no plan meets gives no plan and claims no proof") {
  // No key may be taken: task-b's reset needs the light off after task-a.
  const std::string p = problem("(and (done-a) (done-b))", "(and (at-most-once (on)) (always (not (key))))");
  PlannerOptions bounded;
  bounded.node_limit = 20000;
  const PlannerResult result = plan(p, bounded);
  INFO(result.message);
  CHECK(result.plans.empty());
  CHECK(result.status != PlannerResult::Status::Unsolvable);
  CHECK(result.status != PlannerResult::Status::InternalError);
}

TEST_CASE("a hard sometime-before lets the goal fact come only after the other held") {
  // done-a only after reset has held: an off (or prepare) before task-a ends.
  const std::string p = problem("(done-a)", "(sometime-before (done-a) (reset))");
  const PlannerResult result = plan(p);
  check_valid(p, result);
  CHECK(count_steps(result, "prepare") + count_steps(result, "turn-off") >= 1);
  // Its first condition true in the first state breaks it there: refused by name.
  const PlannerResult broken = plan(problem("(done-b)", "(sometime-before (done-a) (reset))", "", "(done-a)"));
  CHECK(broken.status == PlannerResult::Status::Unsupported);
  CHECK(broken.message.find("sometime-before") != std::string::npos);
}

TEST_CASE("a hard sometime-after makes the second condition follow every state of the first") {
  // Once on, the light must be off at that state or later: the plan ends dark.
  check_constraint_changes_plan("(done-a)", "(sometime-after (on) (not (on)))", "turn-off", 0, 1);
}

TEST_CASE("hold-during and hold-after are kept over their intervals") {
  // Dark over [0, 5): the light comes on at 5 at the earliest, task-a ends at 7.
  const std::string during = problem("(done-a)", "(hold-during 0 5 (not (on)))");
  const PlannerResult late = plan(during);
  check_valid(during, late);
  double makespan = 0.0;
  for (const PlanStep& step : late.best()->plan.steps) {
    makespan = std::max(makespan, step.time.value_or(0.0) + step.duration.value_or(0.0));
  }
  CHECK(makespan >= 7.0 - 1e-6);
  // Lit at every state after 3: the reset must come from prepare, not an off.
  check_constraint_changes_plan("(and (done-a) (reset))", "(hold-after 3 (on))", "turn-off", 1, 0);
}

TEST_CASE("an at-most-once preference is traded by the rounds: kept where it pays") {
  // Lighting twice costs 20; the plan through prepare, no longer, nothing.
  const std::string p = problem("(and (done-a) (done-b))", "(preference once (at-most-once (on)))",
                                "minimize (+ (total-time) (* 20 (is-violated once)))");
  PlannerOptions options;
  options.search = with_anytime(alias("pddl3"));
  options.time_limit = 10.0;
  const PlannerResult result = plan(p, options);
  const ValidationResult v = check_valid(p, result);
  CHECK(v.value < 20.0);  // lit once: no violation
  CHECK(count_steps(result, "turn-on") == 1);
}
