#include "planner/grounding_cache.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>

#include "planner/planner.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

const char* kDomain = R"(
(define (domain deliver) (:requirements :typing :durative-actions :fluents :negative-preconditions)
  (:types place truck package - object)
  (:predicates (at ?x - (either truck package) ?p - place) (road ?a ?b - place) (in ?p - package ?t - truck)
               (dirty ?p - place))
  (:functions (time-to ?a ?b - place))
  (:durative-action drive :parameters (?t - truck ?a ?b - place)
    :duration (= ?duration (time-to ?a ?b))
    :condition (and (at start (at ?t ?a)) (over all (road ?a ?b)))
    :effect (and (at start (not (at ?t ?a))) (at end (at ?t ?b))))
  (:durative-action load :parameters (?p - package ?t - truck ?x - place)
    :duration (= ?duration 1)
    :condition (and (at start (at ?p ?x)) (over all (at ?t ?x)))
    :effect (and (at start (not (at ?p ?x))) (at end (in ?p ?t))))
  (:durative-action sweep :parameters (?t - truck ?x - place)
    :duration (= ?duration 2)
    :condition (over all (at ?t ?x))
    :effect (at end (not (dirty ?x)))))
)";

std::string problem(const std::string& init, const std::string& goal = "(in p1 t1)") {
  return "(define (problem p) (:domain deliver) (:objects t1 - truck a b c island - place p1 - package)"
         " (:init " + init + " (= (time-to a b) 3) (= (time-to b a) 3) (= (time-to b c) 4) (= (time-to island a) 5))"
         " (:goal " + goal + "))";
}

const std::string kRoads = "(road a b) (road b a) (road b c) (road island a)";

std::set<std::string> initial_names(const GroundTask& task) {
  std::set<std::string> names;
  for (FactId f : task.initial_facts) names.insert(task.fact_name(f));
  return names;
}

bool has_action(const GroundTask& task, const std::string& name) {
  return std::any_of(task.actions.begin(), task.actions.end(),
                     [&](const GroundAction& a) { return task.action_name(a) == name; });
}

PlannerResult plan(const std::shared_ptr<const GroundTask>& task) { return Planner(task, PlannerOptions{}).plan(); }

}  // namespace

TEST_CASE("a problem that differs only in its initial state reuses the grounding") {
  const auto first = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) " + kRoads));
  const auto moved = test::load_task_text(kDomain, problem("(at t1 b) (at p1 b) " + kRoads));
  GroundingCache cache;
  cache.ground(*first.domain, *first.problem);
  CHECK_FALSE(cache.last_reused());
  const auto derived = cache.ground(*moved.domain, *moved.problem);
  REQUIRE(cache.last_reused());
  CHECK(cache.statistics().reused == 1);
  CHECK(cache.statistics().grounded == 1);
  const auto fresh = ground(*moved.domain, *moved.problem);
  CHECK(initial_names(*derived) == initial_names(*fresh));
  CHECK(derived->lifted->initial_facts.size() == fresh->lifted->initial_facts.size());
  // The same plan quality from the reused grounding as from a fresh one.
  const PlannerResult a = plan(derived), b = plan(fresh);
  REQUIRE(a.best());
  REQUIRE(b.best());
  CHECK(a.best()->validation.value == Approx(b.best()->validation.value));
  CHECK(a.best()->text.find("(load p1 t1 b)") != std::string::npos);
}

TEST_CASE("a changed goal, a changed static fact or another domain is grounded afresh") {
  const auto first = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) " + kRoads));
  GroundingCache cache;
  cache.ground(*first.domain, *first.problem);

  const auto other_goal = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) " + kRoads, "(at t1 c)"));
  cache.ground(*other_goal.domain, *other_goal.problem);
  CHECK_FALSE(cache.last_reused());
  CHECK(cache.last_miss().find("goal") != std::string::npos);

  // The goal (at t1 c) is the reference now; a road goes.
  const auto no_road =
      test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) (road a b) (road b a) (road island a)", "(at t1 c)"));
  const auto task = cache.ground(*no_road.domain, *no_road.problem);
  CHECK_FALSE(cache.last_reused());
  CHECK(cache.last_miss() == "a static fact no longer holds");
  CHECK_FALSE(has_action(*task, "(drive t1 b c)"));
  CHECK_FALSE(plan(task).best());
}

TEST_CASE("an exogenous predicate is ground as a fluent, so that its changes reuse the grounding") {
  GroundingOptions options;
  options.names.exogenous_predicates = {"road"};
  GroundingCache cache(options);
  const auto first = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) " + kRoads));
  cache.ground(*first.domain, *first.problem);
  // The road from a to b is closed: no way to the package.
  const auto closed = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) (road b a) (road b c) (road island a)"));
  const auto task = cache.ground(*closed.domain, *closed.problem);
  REQUIRE(cache.last_reused());
  CHECK(has_action(*task, "(drive t1 a b)"));  // ground, but its road is a fact that no longer holds
  CHECK_FALSE(plan(task).best());
}

TEST_CASE("a fact the reference never reaches carries its reachability on") {
  const auto first = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) " + kRoads));
  GroundingCache cache;
  const auto reference = cache.ground(*first.domain, *first.problem);
  CHECK_FALSE(has_action(*reference, "(drive t1 island a)"));
  // The truck was towed to the island, which no drive reaches.
  const auto towed = test::load_task_text(kDomain, problem("(at t1 island) (at p1 b) " + kRoads));
  const auto task = cache.ground(*towed.domain, *towed.problem);
  REQUIRE(cache.last_reused());
  CHECK(has_action(*task, "(drive t1 island a)"));
  const PlannerResult result = plan(task);
  REQUIRE(result.best());
  CHECK(result.best()->text.find("(drive t1 island a)") != std::string::npos);
  // The extended grounding serves the next problem too.
  cache.ground(*first.domain, *first.problem);
  CHECK(cache.last_reused());
  CHECK(cache.statistics().grounded == 1);
}

TEST_CASE("a new fact that an action already ground would delete makes the cache ground afresh") {
  const auto clean = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) " + kRoads));
  GroundingCache cache;
  cache.ground(*clean.domain, *clean.problem);
  // (dirty a) was never reachable, so (sweep t1 a) was ground without its
  // delete; reusing it would let the plan believe a stays dirty.
  const auto dirty = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) (dirty a) " + kRoads, "(not (dirty a))"));
  cache.ground(*dirty.domain, *dirty.problem);
  CHECK_FALSE(cache.last_reused());  // the goal differs
  const auto dirty_again = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) " + kRoads, "(not (dirty a))"));
  cache.ground(*dirty_again.domain, *dirty_again.problem);
  CHECK(cache.last_reused());  // fewer facts: reused
  const auto dirty_b =
      test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) (dirty a) (dirty b) " + kRoads, "(not (dirty a))"));
  const auto task = cache.ground(*dirty_b.domain, *dirty_b.problem);
  CHECK_FALSE(cache.last_reused());
  CHECK(cache.last_miss().find("(sweep t1 b)") != std::string::npos);
  const PlannerResult result = plan(task);
  REQUIRE(result.best());
  CHECK(result.best()->text.find("(sweep t1 a)") != std::string::npos);
}

TEST_CASE("planners on the tasks of one cache share their index and relaxed planning graph, and plan the same") {
  const auto first = test::load_task_text(kDomain, problem("(at t1 a) (at p1 b) " + kRoads));
  const auto moved = test::load_task_text(kDomain, problem("(at t1 b) (at p1 b) " + kRoads));
  const auto towed = test::load_task_text(kDomain, problem("(at t1 island) (at p1 b) " + kRoads));
  GroundingCache cache;
  *cache.planner_workspace() = prepare_workspace(cache.ground(*first.domain, *first.problem));
  const std::shared_ptr<const TemporalRpg::Graph> prepared = cache.planner_workspace()->graph;
  for (const auto* loaded : {&moved, &towed}) {
    const auto task = cache.ground(*loaded->domain, *loaded->problem);
    REQUIRE(cache.last_reused());
    const PlannerResult shared = Planner(task, PlannerOptions{}, cache.planner_workspace()).plan();
    const PlannerResult alone = Planner(task, PlannerOptions{}).plan();
    REQUIRE(shared.best());
    REQUIRE(alone.best());
    CHECK(shared.best()->text == alone.best()->text);
    // The index is this task's: the task itself, or its view on the
    // relevant actions (planner/relevance.h), same state and literals.
    CHECK(cache.planner_workspace()->index->task().initial_facts == task->initial_facts);
    CHECK(cache.planner_workspace()->index->task().timed_literals.size() == task->timed_literals.size());
    if (loaded == &moved) CHECK(cache.planner_workspace()->graph == prepared);
  }
  // The moved truck's task shares the prepared graph; the towed one's has
  // new actions, so its planner built a graph of its own.
  CHECK(cache.planner_workspace()->graph != prepared);
}
