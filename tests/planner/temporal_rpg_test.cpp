// The temporal relaxed planning graph's numeric relaxation, seen through
// the planner: what it proves unreachable and what it must keep reachable.
#include "planner/temporal_rpg.h"

#include <catch2/catch.hpp>

#include "planner/grounder.h"
#include "planner/numeric_effect_analysis.h"
#include "planner/partial_plan.h"
#include "planner/planner.h"
#include "planner/task_index.h"
#include "tests/support/ground_names.h"
#include "tests/support/task_loader.h"

using namespace alplan;
using Status = PlannerResult::Status;

namespace {

// `borrow` takes a catalyst at its start and gives it back at its end (as
// pathways' synthesize does); `brew` takes one and gives two back.
const char* const kLab = R"(
(define (domain lab) (:requirements :durative-actions :fluents)
  (:predicates (made))
  (:functions (catalyst))
  (:durative-action borrow :parameters () :duration (= ?duration 2)
    :condition (at start (>= (catalyst) 1))
    :effect (and (at start (decrease (catalyst) 1)) (at end (increase (catalyst) 1)) (at end (made))))
  (:durative-action brew :parameters () :duration (= ?duration 3)
    :condition (and (at start (made)) (at start (>= (catalyst) 1)))
    :effect (and (at start (decrease (catalyst) 1)) (at end (increase (catalyst) 2)))))
)";

std::shared_ptr<const GroundTask> lab(const std::string& init, const std::string& goal) {
  const std::string problem = "(define (problem p) (:domain lab) (:init " + init + ") (:goal " + goal + "))";
  return ground(test::load_task_text(kLab, problem).normalized);
}

// `make` adds one unit and `bake` (needing `made`) three a time unit, each
// at its end.
const char* const kBakery = R"(
(define (domain bakery) (:requirements :durative-actions :fluents)
  (:predicates (made))
  (:functions (stock) (oven))
  (:durative-action make :parameters () :duration (= ?duration 1)
    :effect (and (at end (increase (stock) 1)) (at end (made))))
  (:durative-action bake :parameters () :duration (= ?duration (oven))
    :condition (at start (made))
    :effect (at end (increase (stock) (* 3 ?duration)))))
)";

// The heuristic's h in the initial state of the bakery with `stock` units
// and the goal `goal`.
double bakery_h(double stock, const std::string& goal, bool count_repetitions) {
  const std::string problem = "(define (problem p) (:domain bakery) (:init (= (stock) " + std::to_string(stock) +
                              ") (= (oven) 1)) (:goal " + goal + "))";
  const auto task = ground(test::load_task_text(kBakery, problem).normalized);
  const TaskIndex index(task);
  const PartialPlan plan(index, 0.001);
  SearchState state(static_cast<std::uint32_t>(task->facts.size()), task->initial_values);
  for (FactId f : task->initial_facts) state.set_fact(f, true);
  TemporalRpgOptions options;
  options.count_repetitions = count_repetitions;
  TemporalRpg rpg(index, options);
  return rpg.evaluate(state, plan).h;
}

PlannerResult plan(const std::shared_ptr<const GroundTask>& task) {
  PlannerOptions options;
  options.time_limit = 20.0;
  return Planner(task, options).plan();
}

}  // namespace

TEST_CASE("a give-back at the end is not a producer: borrowing cannot raise what was borrowed") {
  // Without brew, nothing raises the catalyst above 1. Counted as an
  // increase, borrow's give-back made it unbounded in the relaxation and the
  // search had to exhaust the states to find out.
  const std::string domain_without_brew = std::string(kLab).substr(0, std::string(kLab).find("(:durative-action brew")) + ")";
  const auto task = ground(test::load_task_text(domain_without_brew,
                                                "(define (problem p) (:domain lab) (:init (= (catalyst) 1)) "
                                                "(:goal (>= (catalyst) 2)))")
                               .normalized);
  const PlannerResult r = plan(task);
  CHECK(r.status == Status::Unsolvable);
  CHECK_THAT(r.message, Catch::Contains("unreachable even in the relaxation"));
}

TEST_CASE("an effect that gives back more than the start took still produces") {
  const PlannerResult r = plan(lab("(= (catalyst) 1)", "(>= (catalyst) 2)"));
  REQUIRE(r.status == Status::Solved);
  CHECK(r.best()->validation.valid);
  CHECK(r.best()->plan.steps.size() == 2);  // borrow for (made), then brew
}

TEST_CASE("a borrowing action running in the state still gives back: its taking is in the state") {
  const auto task = lab("(= (catalyst) 1)", "(and (made) (>= (catalyst) 1))");
  PlanningStart start;
  start.now = 1.0;
  start.values = task->initial_values;
  start.values[test::variable_named(*task, "(catalyst)")] = 0.0;  // borrow took it at time 0
  RunningAction running;
  running.action = test::action_named(*task, "(borrow)");
  running.min_duration = running.max_duration = 2.0;
  start.running.push_back(running);
  PlannerOptions options;
  options.time_limit = 20.0;
  const PlannerResult r = Planner(task, options).plan_from(start);
  INFO(r.message);
  REQUIRE(r.status == Status::Solved);
  CHECK(r.best()->validation.valid);
}

TEST_CASE("counted repetitions: a goal of n units made one at a time costs n applications") {
  // make: a start and an end, so 2 per application. Without counting, one
  // application met any amount.
  CHECK(bakery_h(0, "(>= (stock) 4)", true) == 8.0);
  CHECK(bakery_h(0, "(>= (stock) 4)", false) == 2.0);
  CHECK(bakery_h(3, "(>= (stock) 4)", true) == 2.0);
  CHECK(bakery_h(4, "(>= (stock) 4)", true) == 0.0);
  // A strict bound met with equality needs one more.
  CHECK(bakery_h(4, "(> (stock) 4)", true) == 2.0);
}

TEST_CASE("counted repetitions: only a constant step is counted") {
  // The first producer reached is make (bake needs made): 1 a step.
  CHECK(bakery_h(0, "(>= (stock) 9)", true) == 18.0);
  const std::string problem = "(define (problem p) (:domain bakery) (:init (= (stock) 0) (= (oven) 1)) (:goal (>= (stock) 4)))";
  const auto task = ground(test::load_task_text(kBakery, problem).normalized);
  const NumericVarId stock = test::variable_named(*task, "(stock)");
  const std::vector<const NumericAssignment*> none;
  for (const GroundAction& g : task->actions) {
    std::vector<const NumericAssignment*> end;
    for (const NumericAssignment& n : g.end.numeric) end.push_back(&n);
    const std::optional<double> up = constant_step(none, end, stock, true);
    if (task->action_name(g) == "(make)") {
      REQUIRE(up);
      CHECK(*up == 1.0);
      CHECK_FALSE(constant_step(none, end, stock, false));  // make never lowers the stock
    } else {
      CHECK_FALSE(up);  // bake's amount reads its duration
    }
  }
}

TEST_CASE("a numeric demand is read only off a sum of variables against a constant") {
  const std::string problem = "(define (problem p) (:domain bakery) (:init (= (stock) 2) (= (oven) 1)) (:goal (made)))";
  const auto task = ground(test::load_task_text(kBakery, problem).normalized);
  const SearchState state(static_cast<std::uint32_t>(task->facts.size()), task->initial_values);
  GroundExpression variable;
  variable.kind = GroundExpression::Kind::Variable;
  variable.variable = test::variable_named(*task, "(stock)");
  GroundExpression five;
  five.value = 5.0;
  GroundComparison at_least{pddl::Comparison::GreaterEqual, variable, five};
  const auto up = numeric_demand(at_least, state);
  REQUIRE(up);
  CHECK(up->upward);
  CHECK(up->gap == 3.0);
  GroundComparison at_most{pddl::Comparison::LessEqual, variable, GroundExpression{}};  // stock <= 0
  const auto down = numeric_demand(at_most, state);
  REQUIRE(down);
  CHECK_FALSE(down->upward);
  CHECK(down->gap == 2.0);
  CHECK_FALSE(numeric_demand({pddl::Comparison::LessEqual, variable, five}, state));  // holds
  CHECK_FALSE(numeric_demand({pddl::Comparison::GreaterEqual, five, variable}, state));  // constant on the left
  CHECK_FALSE(numeric_demand({pddl::Comparison::Equal, variable, five}, state));
}
