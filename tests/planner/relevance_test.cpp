#include "planner/relevance.h"

#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "planner/grounder.h"
#include "planner/grounding_cache.h"
#include "planner/planner.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

// Trucks load packages; sweeping cleans a place; a cleaned place may be
// inspected (a negative condition); polishing pays a cost; fuel is burnt
// by driving and refilled by a pump, and driving needs fuel.
const char* kDomain = R"(
(define (domain relevance) (:requirements :typing :durative-actions :fluents :negative-preconditions)
  (:types place truck package - object)
  (:constants a - place)
  (:predicates (at ?x - (either truck package) ?p - place) (in ?p - package ?t - truck) (dirty ?p - place)
               (inspected ?p - place) (shiny ?t - truck))
  (:functions (fuel ?t - truck) (total-cost))
  (:durative-action drive :parameters (?t - truck ?a ?b - place)
    :duration (= ?duration 2)
    :condition (and (at start (at ?t ?a)) (at start (>= (fuel ?t) 1)))
    :effect (and (at start (not (at ?t ?a))) (at end (at ?t ?b)) (at end (decrease (fuel ?t) 1))))
  (:durative-action pump :parameters (?t - truck ?a - place)
    :duration (= ?duration 1)
    :condition (over all (at ?t ?a))
    :effect (at end (increase (fuel ?t) 5)))
  (:durative-action load :parameters (?p - package ?t - truck ?x - place)
    :duration (= ?duration 1)
    :condition (and (at start (at ?p ?x)) (over all (at ?t ?x)))
    :effect (and (at start (not (at ?p ?x))) (at end (in ?p ?t))))
  (:durative-action sweep :parameters (?t - truck ?x - place)
    :duration (= ?duration 2)
    :condition (over all (at ?t ?x))
    :effect (at end (not (dirty ?x))))
  (:durative-action inspect :parameters (?t - truck ?x - place)
    :duration (= ?duration 1)
    :condition (and (over all (at ?t ?x)) (at start (not (dirty ?x))))
    :effect (at end (inspected ?x)))
  (:durative-action polish :parameters (?t - truck)
    :duration (= ?duration 1)
    :condition (at start (at ?t a))
    :effect (and (at end (shiny ?t)) (at end (increase (total-cost) 3)))))
)";

std::string problem(const std::string& goal) {
  return "(define (problem p) (:domain relevance) (:objects t1 t2 - truck b - place p1 p2 - package)"
         " (:init (at t1 a) (at t2 b) (at p1 b) (at p2 a) (dirty a) (dirty b) (= (fuel t1) 1) (= (fuel t2) 1)"
         " (= (total-cost) 0))"
         " (:goal " + goal + ") (:metric minimize (+ (total-time) (total-cost))))";
}

std::set<std::string> kept(const std::string& goal, const std::vector<std::string>& running = {}) {
  const auto loaded = test::load_task_text(kDomain, problem(goal));
  const auto task = ground(*loaded.domain, *loaded.problem);
  std::vector<ActionId> keep;
  for (ActionId a = 0; a < task->actions.size(); ++a) {
    for (const std::string& r : running) {
      if (task->action_name(task->actions[a]) == r) keep.push_back(a);
    }
  }
  const std::vector<bool> relevant = relevant_actions(*task, keep);
  std::set<std::string> names;
  for (ActionId a = 0; a < task->actions.size(); ++a) {
    if (relevant[a]) names.insert(task->action_name(task->actions[a]));
  }
  return names;
}

bool has_prefix(const std::set<std::string>& names, const std::string& prefix) {
  for (const std::string& n : names) {
    if (n.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("only the actions that can reach the goal are relevant") {
  const std::set<std::string> names = kept("(in p1 t1)");
  CHECK(names.count("(load p1 t1 b)") == 1);
  CHECK(names.count("(drive t1 a b)") == 1);
  // Driving burns fuel a condition reads: pumping is relevant.
  CHECK(names.count("(pump t1 a)") == 1);
  // Nothing the goal needs: another package, the other truck's load, sweeping.
  CHECK(names.count("(load p2 t1 a)") == 0);
  CHECK(names.count("(load p1 t2 b)") == 0);
  CHECK_FALSE(has_prefix(names, "(sweep"));
  CHECK_FALSE(has_prefix(names, "(inspect"));
  // Only a cost: minimising the metric never wants it.
  CHECK_FALSE(has_prefix(names, "(polish"));
}

TEST_CASE("a negative condition makes the deleters of its fact relevant") {
  const std::set<std::string> names = kept("(inspected b)");
  CHECK(names.count("(inspect t1 b)") == 1);
  CHECK(names.count("(sweep t1 b)") == 1);
  CHECK(names.count("(sweep t2 b)") == 1);
  CHECK(names.count("(sweep t1 a)") == 0);
  CHECK_FALSE(has_prefix(names, "(load"));
}

TEST_CASE("a goal on a fact only the costly action adds keeps it, and a running action is kept") {
  CHECK(kept("(shiny t2)").count("(polish t2)") == 1);
  const std::set<std::string> names = kept("(in p1 t1)", {"(sweep t2 a)"});
  CHECK(names.count("(sweep t2 a)") == 1);
}

TEST_CASE("planning on the relevant actions finds the plan the whole task has") {
  const auto loaded = test::load_task_text(kDomain, problem("(and (in p1 t1) (in p2 t2))"));
  const auto task = ground(*loaded.domain, *loaded.problem);
  const RelevantView view = relevant_view(task);
  CHECK(view.pruned > 0);
  CHECK(view.task->actions.size() + view.pruned == task->actions.size());
  PlannerOptions whole;
  whole.prune_irrelevant = false;
  const PlannerResult a = Planner(task, PlannerOptions{}).plan();
  const PlannerResult b = Planner(task, whole).plan();
  REQUIRE(a.best());
  REQUIRE(b.best());
  CHECK(a.best()->validation.valid);
  CHECK(a.best()->validation.value == Approx(b.best()->validation.value));
  CHECK(a.statistics.evaluated <= b.statistics.evaluated);
}

TEST_CASE("a workspace keeps the relevant view for tasks sharing the ground actions and goal") {
  const auto first = test::load_task_text(kDomain, problem("(in p1 t1)"));
  GroundingCache cache;
  const auto task = cache.ground(*first.domain, *first.problem);
  auto workspace = cache.planner_workspace();
  *workspace = prepare_workspace(task);
  REQUIRE(workspace->relevance);
  const auto relevance = workspace->relevance;
  const PlannerResult result = Planner(task, PlannerOptions{}, workspace).plan();
  REQUIRE(result.best());
  CHECK(workspace->relevance == relevance);
  CHECK(same_ground_actions(workspace->index->task(), *relevance->view.task));
}

namespace {

// `finish` reaches g but, when p holds, spoils q; `clear` makes p false.
// With p and q at first, the only plan clears p before finishing.
const char* kSpoiler = R"(
(define (domain spoiler) (:requirements :strips :conditional-effects :fluents)
  (:predicates (p) (q) (g))
  (:functions (score))
  (:action finish :parameters () :precondition (and) :effect (and (g) (when (p) (not (q)))))
  (:action clear :parameters () :precondition (p) :effect (not (p)))
  (:action earn :parameters () :precondition (g) :effect (increase (score) 1)))
)";

}  // namespace

TEST_CASE("an action that keeps a conditional effect from firing is relevant") {
  const auto loaded = test::load_task_text(
      kSpoiler, "(define (problem s) (:domain spoiler) (:init (p) (q) (= (score) 0)) (:goal (and (g) (q))))");
  const auto task = ground(*loaded.domain, *loaded.problem);
  const std::vector<bool> relevant = relevant_actions(*task);
  for (ActionId a = 0; a < task->actions.size(); ++a) {
    const std::string name = task->action_name(task->actions[a]);
    INFO(name);
    CHECK(relevant[a] == (name != "(earn)"));
  }
  const PlannerResult result = Planner(task, PlannerOptions{}).plan();
  REQUIRE(result.best());
  CHECK(result.best()->text.find("(clear)") != std::string::npos);
}

TEST_CASE("a metric that rewards an action keeps the action") {
  const auto loaded = test::load_task_text(
      kSpoiler, "(define (problem s) (:domain spoiler) (:init (= (score) 0)) (:goal (g))"
                " (:metric minimize (- 0 (score))))");
  const auto task = ground(*loaded.domain, *loaded.problem);
  const std::vector<bool> relevant = relevant_actions(*task);
  bool earn = false;
  for (ActionId a = 0; a < task->actions.size(); ++a) {
    if (task->action_name(task->actions[a]) == "(earn)") earn = relevant[a];
  }
  CHECK(earn);
}

// Issue 44: opening the door needs nothing, but `always` forbids the light
// and the open door together, so switching the light off is needed; pruned
// as irrelevant, the task ran to its time limit.
TEST_CASE("an action needed only to keep an always constraint true is relevant and the task plans") {
  const char* const domain = R"(
(define (domain door) (:requirements :strips :durative-actions :negative-preconditions :constraints)
  (:predicates (lit) (open))
  (:durative-action switch-off :parameters () :duration (= ?duration 1)
    :condition (at start (lit)) :effect (at end (not (lit))))
  (:durative-action open-door :parameters () :duration (= ?duration 3)
    :condition (at start (not (open))) :effect (at end (open))))
)";
  const char* const problem_text = R"(
(define (problem d) (:domain door) (:init (lit)) (:goal (open))
  (:constraints (always (or (not (lit)) (not (open))))))
)";
  const auto loaded = test::load_task_text(domain, problem_text);
  const auto task = ground(*loaded.domain, *loaded.problem);
  const std::vector<bool> relevant = relevant_actions(*task);
  for (ActionId a = 0; a < task->actions.size(); ++a) {
    INFO(task->action_name(task->actions[a]));
    CHECK(relevant[a]);
  }
  PlannerOptions options;
  options.time_limit = 10.0;
  const PlannerResult result = Planner(task, options).plan();
  INFO(result.message);
  CHECK(result.status == PlannerResult::Status::Solved);
}
