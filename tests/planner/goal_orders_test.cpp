// Goal orders from h^2 mutexes (planner/goal_orders.h) on a floor-tile
// column: a painted tile cannot be stood on, so the tile above must be
// painted first; and the planner pruning with them on floor-tile 2011
// instance 3, which it solved in 160,000 expansions without them and in
// 1,600 with them (measured; limited by nodes here, not time).
#include <catch2/catch.hpp>

#include <algorithm>

#include "planner/fact_pair_mutexes.h"
#include "planner/goal_orders.h"
#include "planner/grounder.h"
#include "planner/planner.h"
#include "tests/support/ground_names.h"
#include "tests/support/task_loader.h"
#include "tests/support/test_paths.h"

using namespace alplan;
using Status = PlannerResult::Status;

namespace {

const char* const kColumn = R"(
(define (domain column) (:requirements :typing :durative-actions)
  (:types robot tile)
  (:predicates (at ?r - robot ?t - tile) (clear ?t - tile) (painted ?t - tile) (up ?y ?x - tile))
  (:durative-action paint-up :parameters (?r - robot ?y ?x - tile) :duration (= ?duration 2)
    :condition (and (at start (at ?r ?x)) (at start (clear ?y)) (over all (up ?y ?x)))
    :effect (and (at start (not (clear ?y))) (at end (painted ?y))))
  (:durative-action paint-down :parameters (?r - robot ?y ?x - tile) :duration (= ?duration 2)
    :condition (and (at start (at ?r ?x)) (at start (clear ?y)) (over all (up ?x ?y)))
    :effect (and (at start (not (clear ?y))) (at end (painted ?y))))
  (:durative-action move :parameters (?r - robot ?x ?y - tile) :duration (= ?duration 1)
    :condition (and (at start (at ?r ?x)) (at start (clear ?y)))
    :effect (and (at start (not (at ?r ?x))) (at start (not (clear ?y))) (at end (at ?r ?y)) (at end (clear ?x)))))
)";

// t0 at the bottom, t3 at the top; moves only between neighbours.
std::string column_problem(const std::string& goal) {
  return R"((define (problem p) (:domain column) (:objects r - robot t0 t1 t2 t3 - tile)
  (:init (at r t0) (clear t1) (clear t2) (clear t3) (up t1 t0) (up t2 t1) (up t3 t2))
  (:goal (and )" + goal + R"()))
)";
}

std::shared_ptr<const GroundTask> column(const std::string& goal) {
  return ground(test::load_task_text(kColumn, column_problem(goal)).normalized);
}

}  // namespace

TEST_CASE("h^2 finds that a painted tile is never stood on, and two painted tiles can hold together",
          "[goal-orders]") {
  const auto task = column("(painted t2) (painted t3)");
  const FactPairMutexes mutexes(*task, task->initial_facts);
  REQUIRE(mutexes.analysed());
  const FactId painted2 = test::fact_named(*task, "(painted t2)");
  const FactId painted3 = test::fact_named(*task, "(painted t3)");
  CHECK_FALSE(mutexes.reachable(test::fact_named(*task, "(at r t2)"), painted2));
  CHECK_FALSE(mutexes.reachable(test::fact_named(*task, "(clear t2)"), painted2));
  CHECK_FALSE(mutexes.reachable(test::fact_named(*task, "(at r t1)"), test::fact_named(*task, "(clear t1)")));
  CHECK(mutexes.reachable(painted2, painted3));
  CHECK(mutexes.reachable(test::fact_named(*task, "(at r t1)"), painted2));
}

TEST_CASE("The top tile is painted before the one below it, and that one before the next (obedient orders)",
          "[goal-orders]") {
  const auto task = column("(painted t1) (painted t2) (painted t3)");
  const GoalOrders orders(*task, task->initial_facts);
  const FactId p1 = test::fact_named(*task, "(painted t1)");
  const FactId p2 = test::fact_named(*task, "(painted t2)");
  const FactId p3 = test::fact_named(*task, "(painted t3)");
  // t3 can only be painted from t2; t2 from t1 or t3, and t3 is painted
  // first; so t2 from t1, before t1 is.
  std::vector<GoalOrder> found = orders.orders();
  CHECK(std::count(found.begin(), found.end(), GoalOrder{p3, p2}) == 1);
  CHECK(std::count(found.begin(), found.end(), GoalOrder{p2, p1}) == 1);
  // Not closed under transitivity: t3 can still be painted from t2 after t1
  // was painted down from t2; the two direct orders prune what it would.
  CHECK(std::count(found.begin(), found.end(), GoalOrder{p3, p1}) == 0);
  CHECK(std::count(found.begin(), found.end(), GoalOrder{p2, p3}) == 0);
  CHECK(std::count(found.begin(), found.end(), GoalOrder{p1, p2}) == 0);

  SearchState state(task->facts.size(), task->initial_values);
  for (FactId f : task->initial_facts) state.set_fact(f, true);
  CHECK_FALSE(orders.broken_by(state));
  state.set_fact(p2, true);
  REQUIRE(orders.broken_by(state));
  CHECK(orders.broken_by(state)->before == p3);
  // t3 still being painted keeps the state alive: both may end in either order.
  state.start({test::action_named(*task, "(paint-up r t3 t2)"), 0, 2.0, 2.0});
  CHECK_FALSE(orders.broken_by(state));
  // t2's painting under way counts as t2 painted.
  SearchState started(task->facts.size(), task->initial_values);
  started.start({test::action_named(*task, "(paint-up r t2 t1)"), 0, 2.0, 2.0});
  CHECK(orders.broken_by(started));
}

TEST_CASE("Goals that do not constrain each other, goals an action deletes, and goals already true are not ordered",
          "[goal-orders]") {
  // t1 and t3 are painted from t0 and t2 (up) or t2 (down): neither walls
  // the other off.
  CHECK(GoalOrders(*column("(painted t1) (painted t3)"), column("(painted t1) (painted t3)")->initial_facts).empty());
  // `clear` is deleted by moves: not a goal that stays.
  const auto task = column("(painted t3) (clear t2)");
  CHECK(GoalOrders(*task, task->initial_facts).empty());
  // From a start where t3 is already painted, only t2 and t1 are ordered.
  const auto three = column("(painted t1) (painted t2) (painted t3)");
  std::vector<FactId> start = three->initial_facts;
  start.erase(std::remove(start.begin(), start.end(), test::fact_named(*three, "(clear t3)")), start.end());
  start.push_back(test::fact_named(*three, "(painted t3)"));
  const GoalOrders from_painted(*three, start);
  REQUIRE(from_painted.orders().size() == 1);
  CHECK(from_painted.orders().front() ==
        GoalOrder{test::fact_named(*three, "(painted t2)"), test::fact_named(*three, "(painted t1)")});
}

TEST_CASE("Tasks above the work bound are not analysed, and every pair counts as reachable", "[goal-orders]") {
  const auto task = column("(painted t1) (painted t2) (painted t3)");
  FactPairMutexOptions options;
  options.max_work_per_round = 10;
  const FactPairMutexes mutexes(*task, task->initial_facts, options);
  CHECK_FALSE(mutexes.analysed());
  CHECK(mutexes.reachable(test::fact_named(*task, "(at r t2)"), test::fact_named(*task, "(painted t2)")));
}

TEST_CASE("Pruning by goal orders solves floor-tile 2011 instance 3 within a node limit that stops the search without",
          "[goal-orders]") {
  const std::string dir = test::benchmarks_dir() + "/ipc/ipc-2011/floor-tile-temporal-satisficing/";
  const test::LoadedTask task = test::load_task(dir + "domain.pddl", dir + "instances/instance-3.pddl");
  PlannerOptions options;
  options.node_limit = 40'000;
  const PlannerResult with = Planner(ground(task.normalized), options).plan();
  REQUIRE(with.status == Status::Solved);
  CHECK(with.best()->validation.valid);
  DefaultSearchKnobs no_orders;
  no_orders.goal_orders = false;
  options.search = parse_search_configuration(default_expression(no_orders));
  const PlannerResult without = Planner(ground(task.normalized), options).plan();
  CHECK(without.status == Status::LimitReached);
}

TEST_CASE("Each conditional effect becomes its own compressed action, with only its own condition and adds",
          "[goal-orders]") {
  const char* const domain = R"(
(define (domain switches) (:requirements :conditional-effects)
  (:predicates (a) (b) (c) (d))
  (:action set-a :parameters () :precondition () :effect (a))
  (:action set-c :parameters () :precondition () :effect (c))
  (:action flip :parameters () :precondition () :effect (and (when (a) (b)) (when (c) (d)))))
)";
  const auto task =
      ground(test::load_task_text(domain, "(define (problem p) (:domain switches) (:goal (and (b) (d))))").normalized);
  const FactId a = test::fact_named(*task, "(a)");
  const FactId b = test::fact_named(*task, "(b)");
  const FactId c = test::fact_named(*task, "(c)");
  const FactId d = test::fact_named(*task, "(d)");
  const std::vector<CompressedAction> actions = compress_actions(*task);
  auto has = [&](const std::vector<FactId>& pre, const std::vector<FactId>& add) {
    return std::any_of(actions.begin(), actions.end(),
                       [&](const CompressedAction& x) { return x.pre == pre && x.add == add; });
  };
  CHECK(has({a}, {b}));
  CHECK(has({c}, {d}));
  CHECK_FALSE(has({std::min(a, c), std::max(a, c)}, {std::min(b, d), std::max(b, d)}));
}
