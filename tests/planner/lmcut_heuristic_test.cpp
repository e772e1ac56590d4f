// The landmark-cut heuristic (planner/lmcut_heuristic.h): its value on
// small tasks computed by hand, the cost a running action still owes, dead
// ends, and A* on it finding plans exactly as cheap as uniform-cost search.
#include "planner/lmcut_heuristic.h"

#include <catch2/catch.hpp>

#include "planner/grounder.h"
#include "planner/planner.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

std::shared_ptr<const GroundTask> ground_text(const std::string& domain, const std::string& problem) {
  return ground(test::load_task_text(domain, problem).normalized);
}

SearchState initial_state(const GroundTask& task) {
  SearchState state(static_cast<std::uint32_t>(task.facts.size()), task.initial_values);
  for (FactId f : task.initial_facts) state.set_fact(f, true);
  return state;
}

ActionId action_named(const GroundTask& task, const std::string& part) {
  for (ActionId a = 0; a < task.actions.size(); ++a) {
    if (task.action_name(task.actions[a]).find(part) != std::string::npos) return a;
  }
  FAIL("no action " << part);
  return 0;
}

// Two goals: one for 3, the other for 4, or both at once for 10. h_max says
// 4 (the dearer goal), the additive heuristic 3 + 4 + 10 counted loosely;
// the optimum, 7, is what LM-cut finds: a cut {second, both} of 4, then
// {first, both} of 3 once both's cost is down to 6.
const char* kTwoGoals = R"(
(define (domain two-goals) (:requirements :strips :numeric-fluents)
  (:predicates (s) (g1) (g2))
  (:functions (total-cost))
  (:action first :parameters () :precondition (s) :effect (and (g1) (increase (total-cost) 3)))
  (:action second :parameters () :precondition (s) :effect (and (g2) (increase (total-cost) 4)))
  (:action both :parameters () :precondition (s) :effect (and (g1) (g2) (increase (total-cost) 10))))
)";
const char* kTwoGoalsProblem =
    "(define (problem p) (:domain two-goals) (:init (s) (= (total-cost) 0)) (:goal (and (g1) (g2)))"
    " (:metric minimize (total-cost)))";

// A chain a -> b -> c of durative moves costing 2 and 5 at their ends, and
// a direct a -> c costing 9; and a note that can only be left at a.
const char* kChain = R"(
(define (domain chain) (:requirements :durative-actions :numeric-fluents)
  (:predicates (at-a) (at-b) (at-c) (noted))
  (:functions (total-cost))
  (:durative-action ab :parameters () :duration (= ?duration 2)
    :condition (at start (at-a)) :effect (and (at start (not (at-a))) (at end (at-b)) (at end (increase (total-cost) 2))))
  (:durative-action bc :parameters () :duration (= ?duration 2)
    :condition (at start (at-b)) :effect (and (at start (not (at-b))) (at end (at-c)) (at end (increase (total-cost) 5))))
  (:durative-action ac :parameters () :duration (= ?duration 1)
    :condition (at start (at-a)) :effect (and (at start (not (at-a))) (at end (at-c)) (at end (increase (total-cost) 9))))
  (:action note :parameters () :precondition (at-a) :effect (noted)))
)";
std::string chain_problem(const std::string& goal) {
  return "(define (problem p) (:domain chain) (:init (at-a) (= (total-cost) 0)) (:goal " + goal +
         ") (:metric minimize (total-cost)))";
}

PlannerResult optimal(const std::shared_ptr<const GroundTask>& task, const std::string& heuristic) {
  PlannerOptions options;
  options.search = parse_search_configuration("complete(wastar(" + heuristic + ", w=1, order=metric, preferred=false))");
  options.time_limit = 20.0;
  return Planner(task, options).plan();
}

}  // namespace

TEST_CASE("lmcut: the optimum of two goals that share a dear action, where h_max sees only the dearer goal") {
  const auto task = ground_text(kTwoGoals, kTwoGoalsProblem);
  const TaskIndex index(task);
  LmCutHeuristic lmcut(index, std::make_shared<LinearMetric>(*linear_metric(*task)));
  CHECK(lmcut.estimate(initial_state(*task)) == Approx(7.0));
  // Without a metric it counts actions: two are needed, or one (both).
  LmCutHeuristic unit(index, nullptr);
  CHECK(unit.estimate(initial_state(*task)) == Approx(1.0));
}

TEST_CASE("lmcut: a running action owes its end's cost, and its end is free to the relaxation") {
  const auto task = ground_text(kChain, chain_problem("(at-c)"));
  const TaskIndex index(task);
  LmCutHeuristic lmcut(index, std::make_shared<LinearMetric>(*linear_metric(*task)));
  const SearchState start = initial_state(*task);
  CHECK(lmcut.estimate(start) == Approx(7.0));  // ab then bc, 2 + 5, under ac's 9
  // ab has started: at-a is gone, at-b not yet there. It owes 2, and bc 5 remains.
  SearchState moving = start;
  const ActionId ab = action_named(*task, "(ab)");
  for (FactId f : task->actions[ab].start.del) moving.set_fact(f, false);
  moving.start(RunningAction{ab, kNoId, 2.0, 2.0});
  CHECK(lmcut.estimate(moving) == Approx(2.0 + 5.0));
  HeuristicValue value = lmcut.evaluate(moving, PartialPlan(index, 0.001));
  CHECK(value.cost == Approx(7.0));
  CHECK(value.h == Approx(8.0));  // not a goal: 1 + the estimate
}

TEST_CASE("lmcut: a goal the relaxation never reaches is a dead end, and named") {
  const auto task = ground_text(kChain, chain_problem("(and (at-c) (noted))"));
  const TaskIndex index(task);
  LmCutHeuristic lmcut(index, std::make_shared<LinearMetric>(*linear_metric(*task)));
  CHECK_FALSE(lmcut.evaluate(initial_state(*task), PartialPlan(index, 0.001), Relaxation::Sound).dead_end());
  // Once the robot has left a without the note, nothing brings it back.
  SearchState left = initial_state(*task);
  const ActionId ab = action_named(*task, "(ab)");
  for (FactId f : task->actions[ab].start.del) left.set_fact(f, false);
  left.start(RunningAction{ab, kNoId, 2.0, 2.0});
  const HeuristicValue value = lmcut.evaluate(left, PartialPlan(index, 0.001), Relaxation::Sound);
  CHECK(value.dead_end());
  REQUIRE(lmcut.unreached_goals().size() == 1);
  CHECK(task->fact_name(lmcut.unreached_goals().front()) == "(noted)");
}

TEST_CASE("lmcut: A* on it finds plans as cheap as uniform-cost search") {
  for (const auto& [domain, problem, best] :
       {std::tuple{kTwoGoals, std::string(kTwoGoalsProblem), 7.0},
        std::tuple{kChain, chain_problem("(at-c)"), 7.0}}) {
    const auto task = ground_text(domain, problem);
    const PlannerResult blind = optimal(task, "blind");
    const PlannerResult lmcut = optimal(task, "lmcut");
    REQUIRE(blind.best());
    REQUIRE(lmcut.best());
    CHECK(blind.best()->validation.metric.value_or(-1) == Approx(best));
    CHECK(lmcut.best()->validation.metric.value_or(-1) == Approx(best));
  }
}

TEST_CASE("lmcut: the configuration language names it") {
  CHECK(parse_search_configuration("complete(wastar(lmcut, w=1, order=metric))").engine.heuristic.kind ==
        HeuristicSpec::Kind::LmCut);
  CHECK_THROWS_WITH(parse_search_configuration("gbfs(lmcut(fast=true))"), Catch::Contains("lmcut takes no options"));
}

TEST_CASE("only A* on an admissible heuristic proves its first plan cost-optimal") {
  const auto proves = [](const std::string& e) { return proves_cost_optimal(parse_search_configuration(e).engine); };
  CHECK(proves("complete(wastar(lmcut, w=1, order=metric, preferred=false))"));
  CHECK(proves("complete(wastar(blind, w=1, order=metric, preferred=false))"));
  CHECK_FALSE(proves("complete(wastar(trpg, w=1, order=metric, preferred=false))"));  // can overestimate
  CHECK_FALSE(proves("complete(wastar(lmcut, w=1, order=metric))"));                   // a second queue
  CHECK_FALSE(proves("complete(wastar(lmcut, w=1, order=metric, preferred=false, deferred=true))"));
  CHECK_FALSE(proves("complete(wastar(lmcut, w=2, order=metric, preferred=false))"));
  CHECK_FALSE(proves("complete(wastar(lmcut, w=1, preferred=false))"));  // steps, not the metric
  CHECK_FALSE(proves("wastar(lmcut, w=1, order=metric, preferred=false)"));
}
