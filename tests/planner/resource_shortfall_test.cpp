// The resource balance of the heuristic (planner/resource_shortfall.h):
// how many recharges a relaxed plan's moves need, from what a charge can
// give, and which way an action moves a variable.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "planner/continuous_change.h"
#include "planner/grounder.h"
#include "planner/partial_plan.h"
#include "planner/resource_shortfall.h"
#include "planner/task_index.h"
#include "tests/support/ground_names.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

// Moves drain 2 per unit over 10 units (20 each) and must keep 5 in
// reserve; a charge gives 5 per unit, at most until full.
const char* kDomain = R"(
(define (domain battery)
  (:requirements :typing :durative-actions :fluents :continuous-effects :duration-inequalities)
  (:types robot place)
  (:predicates (at ?r - robot ?p - place) (dock ?p - place) (link ?a ?b - place))
  (:functions (battery ?r - robot) (capacity ?r - robot) (reserve ?r - robot))
  (:durative-action move
    :parameters (?r - robot ?a ?b - place)
    :duration (= ?duration 10)
    :condition (and (at start (at ?r ?a)) (over all (link ?a ?b))
                    (over all (>= (battery ?r) (reserve ?r))))
    :effect (and (at start (not (at ?r ?a))) (at end (at ?r ?b))
                 (decrease (battery ?r) (* #t 2))))
  (:durative-action charge
    :parameters (?r - robot ?p - place)
    :duration (and (>= ?duration 1) (<= ?duration (/ (- (capacity ?r) (battery ?r)) 5)))
    :condition (and (over all (at ?r ?p)) (at start (dock ?p))
                    (over all (<= (battery ?r) (capacity ?r))))
    :effect (increase (battery ?r) (* #t 5))))
)";

std::string problem(int battery, int capacity) {
  return R"((define (problem three-moves) (:domain battery)
  (:objects r - robot a b c d - place)
  (:init (at r a) (dock a) (link a b) (link b c) (link c d)
         (= (battery r) )" +
         std::to_string(battery) + ") (= (capacity r) " + std::to_string(capacity) + R"() (= (reserve r) 5))
  (:goal (at r d)))
)";
}

struct Fixture {
  std::shared_ptr<const GroundTask> task;
  std::shared_ptr<const ContinuousModel> model;
  std::unique_ptr<TaskIndex> index;
  std::unique_ptr<PartialPlan> plan;
  SearchState state;

  Fixture(int battery, int capacity) {
    task = ground(test::load_task_text(kDomain, problem(battery, capacity)).normalized);
    model = ContinuousModel::build(*task);
    REQUIRE(model);
    index = std::make_unique<TaskIndex>(task);
    plan = std::make_unique<PartialPlan>(*index, 0.001);
    state = SearchState(static_cast<std::uint32_t>(task->facts.size()), task->initial_values);
    for (FactId f : task->initial_facts) state.set_fact(f, true);
  }
  ActionId action(const std::string& name) const { return test::action_named(*task, name); }
  std::vector<ResourceShortfall> shortfalls(const std::vector<ActionId>& relaxed) const {
    ShortfallInput input;
    input.state = &state;
    input.plan = plan.get();
    input.relaxed_starts = relaxed;
    input.min_duration = [](ActionId) { return 10.0; };
    input.greatest = [this](NumericVarId v) { return state.value(v); };
    return ResourceBalance(*task, *model).shortfalls(input);
  }
  std::vector<ActionId> three_moves() const {
    return {action("(move r a b)"), action("(move r b c)"), action("(move r c d)")};
  }
};

}  // namespace

TEST_CASE("resource balance: moves that drain more than the battery holds need charges") {
  SECTION("30 held, 60 used, 5 kept: 35 short; a charge from the reserve to 40 gives 35, so one") {
    const Fixture f(30, 40);
    const std::vector<ResourceShortfall> s = f.shortfalls(f.three_moves());
    REQUIRE(s.size() == 1);
    CHECK(f.task->variable_name(s[0].variable) == "(battery r)");
    CHECK(s[0].amount == Approx(35.0));
    CHECK(s[0].applications == 1.0);
    REQUIRE(s[0].producers.size() == 1);  // the charge at the dock (the grounder drops the others)
  }
  SECTION("a battery of 20 is charged 15 at most: three charges") {
    const Fixture f(20, 20);
    const std::vector<ResourceShortfall> s = f.shortfalls(f.three_moves());
    REQUIRE(s.size() == 1);
    CHECK(s[0].amount == Approx(45.0));
    CHECK(s[0].applications == 3.0);
  }
  SECTION("enough charge: no shortfall") {
    const Fixture f(70, 100);
    CHECK(f.shortfalls(f.three_moves()).empty());
  }
  SECTION("a charge in the relaxed plan counts: only what it cannot give is short") {
    const Fixture f(20, 20);
    std::vector<ActionId> relaxed = f.three_moves();
    relaxed.push_back(f.action("(charge r a)"));
    const std::vector<ResourceShortfall> s = f.shortfalls(relaxed);
    REQUIRE(s.size() == 1);
    CHECK(s[0].amount == Approx(30.0));
    CHECK(s[0].applications == 2.0);
  }
  SECTION("the greatest value a schedule allows is what counts") {
    Fixture f(30, 100);
    ShortfallInput input;
    input.state = &f.state;
    input.plan = f.plan.get();
    input.relaxed_starts = f.three_moves();
    input.min_duration = [](ActionId) { return 10.0; };
    input.greatest = [](NumericVarId) { return 65.0; };  // an earlier charge may run longer
    CHECK(ResourceBalance(*f.task, *f.model).shortfalls(input).empty());
  }
}

TEST_CASE("resource balance: which way actions and conditions move a variable") {
  const Fixture f(30, 40);
  const ActionId move = f.action("(move r a b)"), charge = f.action("(charge r a)");
  const NumericVarId battery = f.task->actions[move].continuous.front().variable;
  CHECK(change_direction(*f.model, f.task->actions[move], battery, f.state) == -1);
  CHECK(change_direction(*f.model, f.task->actions[charge], battery, f.state) == 1);
  const auto invariants = [&](ActionId a) {
    return f.model->step(f.task->actions[a], SnapKind::Start, f.state, std::nan(""))->invariants;
  };
  CHECK(bound_direction(invariants(move), battery) == 1);     // must not fall below the reserve
  CHECK(bound_direction(invariants(charge), battery) == -1);  // must not pass capacity
}
