#include "planner/grounder.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <set>
#include <sstream>

#include "planner/ground_printer.h"
#include "planner/plan.h"
#include "benchmarks/harness/suite.h"
#include "tests/support/task_loader.h"
#include "tests/support/test_paths.h"

using namespace alplan;

namespace {

std::shared_ptr<const GroundTask> ground_text(const std::string& domain, const std::string& problem) {
  return ground(test::load_task_text(domain, problem).normalized);
}

std::set<std::string> action_names(const GroundTask& task) {
  std::set<std::string> names;
  for (const GroundAction& a : task.actions) names.insert(task.action_name(a));
  return names;
}

const char* kLogistics = R"(
(define (domain logistics) (:requirements :typing :durative-actions :fluents)
  (:types place vehicle - object truck - vehicle package - object)
  (:predicates (at ?x - (either vehicle package) ?p - place) (road ?a ?b - place) (in ?p - package ?v - vehicle))
  (:functions (time-to ?a ?b - place) (fuel ?v - vehicle))
  (:durative-action drive :parameters (?t - truck ?a ?b - place)
    :duration (= ?duration (time-to ?a ?b))
    :condition (and (at start (at ?t ?a)) (over all (road ?a ?b)) (at start (> (fuel ?t) 1)))
    :effect (and (at start (not (at ?t ?a))) (at end (at ?t ?b)) (at end (decrease (fuel ?t) 1))))
  (:durative-action load :parameters (?p - package ?t - truck ?x - place)
    :duration (= ?duration 1)
    :condition (and (at start (at ?p ?x)) (over all (at ?t ?x)))
    :effect (and (at start (not (at ?p ?x))) (at end (in ?p ?t)))))
)";

const char* kLogisticsProblem = R"(
(define (problem p) (:domain logistics)
  (:objects t1 - truck a b c island - place p1 - package)
  (:init (at t1 a) (at p1 b) (road a b) (road b a) (road b c) (road island a)
         (= (time-to a b) 3) (= (time-to b a) 3) (= (time-to b c) 4) (= (fuel t1) 10))
  (:goal (in p1 t1)))
)";

}  // namespace

TEST_CASE("grounding keeps only reachable actions") {
  auto task = ground_text(kLogistics, kLogisticsProblem);
  const std::set<std::string> names = action_names(*task);
  CHECK(names.count("(drive t1 a b)"));
  CHECK(names.count("(drive t1 b c)"));
  CHECK(names.count("(load p1 t1 b)"));
  // No road from c, and t1 never reaches the island: these never exist.
  CHECK_FALSE(names.count("(drive t1 island a)"));
  CHECK_FALSE(names.count("(drive t1 c b)"));
  CHECK_FALSE(names.count("(load p1 t1 a)"));  // p1 is never at a
  CHECK(task->actions.size() == names.size());
}

TEST_CASE("static facts and static numbers are compiled away, fluents stay") {
  auto task = ground_text(kLogistics, kLogisticsProblem);
  // road is static: no fact for it.
  for (FactId f = 0; f < task->facts.size(); ++f) CHECK(task->fact_name(f).find("(road") == std::string::npos);
  const GroundAction* drive = nullptr;
  for (const GroundAction& a : task->actions) {
    if (task->action_name(a) == "(drive t1 b c)") drive = &a;
  }
  REQUIRE(drive);
  CHECK(drive->over_all.empty());  // (road b c) held statically
  REQUIRE(drive->duration.size() == 1);
  CHECK(drive->duration[0].value.kind == GroundExpression::Kind::Constant);
  CHECK(drive->duration[0].value.value == 4);
  REQUIRE(drive->at_start.numeric.size() == 1);
  CHECK(write_comparison(*task, drive->at_start.numeric[0]) == "(> (fuel t1) 1)");
  CHECK(task->numeric.size() == 1);
  CHECK(task->initial_values == std::vector<double>{10});
}

TEST_CASE("grounding is deterministic") {
  std::ostringstream first, second;
  dump(*ground_text(kLogistics, kLogisticsProblem), first);
  dump(*ground_text(kLogistics, kLogisticsProblem), second);
  CHECK(first.str() == second.str());
  const std::string dir = test::benchmarks_dir() + "/ipc/ipc-2004/airport-temporal-time-windows-adl/";
  std::ostringstream a, b;
  dump(*ground(test::load_task(dir + "domain.pddl", dir + "instances/instance-3.pddl").normalized), a);
  dump(*ground(test::load_task(dir + "domain.pddl", dir + "instances/instance-3.pddl").normalized), b);
  CHECK(a.str() == b.str());
}

TEST_CASE("quantifiers expand over their types, conditional effects stay conditional") {
  const char* domain = R"(
(define (domain lights) (:requirements :adl :typing)
  (:types room lamp)
  (:predicates (in ?l - lamp ?r - room) (on ?l - lamp) (dark ?r - room) (here ?r - room))
  (:action switch-all :parameters (?r - room)
    :precondition (and (here ?r) (exists (?l - lamp) (in ?l ?r)))
    :effect (forall (?l - lamp) (when (in ?l ?r) (on ?l))))
  (:action leave :parameters (?r - room)
    :precondition (and (here ?r) (forall (?l - lamp) (imply (in ?l ?r) (on ?l))))
    :effect (and (not (here ?r)) (forall (?l - lamp) (when (on ?l) (not (on ?l)))))))
)";
  const char* problem = "(define (problem p) (:domain lights) (:objects r1 r2 - room l1 l2 l3 - lamp)"
                        " (:init (here r1) (in l1 r1) (in l2 r1) (in l3 r2)) (:goal (not (here r1))))";
  auto task = ground_text(domain, problem);
  const std::set<std::string> names = action_names(*task);
  CHECK(names == std::set<std::string>{"(switch-all r1)", "(leave r1)"});
  for (const GroundAction& a : task->actions) {
    if (task->action_name(a) == "(switch-all r1)") {
      // (in l ?r) is static: the when-conditions fold to true for l1, l2.
      CHECK(write_effects(*task, a.start) == "(and (on l1) (on l2))");
      CHECK(write_condition(*task, a.at_start) == "(here r1)");
    } else {
      CHECK(write_condition(*task, a.at_start) == "(and (here r1) (on l1) (on l2))");
      REQUIRE(a.start.conditional.size() == 3);  // (on l) is a fluent: conditional per lamp
      CHECK(write_effects(*task, a.start).find("(when (on l3) (not (on l3)))") != std::string::npos);
    }
  }
}

TEST_CASE("either types and multiple inheritance give the right objects") {
  const char* domain = R"(
(define (domain zoo) (:requirements :typing)
  (:types animal - object pet - animal amphibian - (either land water) frog - amphibian)
  (:predicates (fed ?x - animal) (wet ?x - water) (walks ?x - (either land pet)))
  (:action feed :parameters (?x - (either pet water)) :precondition (and) :effect (and)))
)";
  const char* problem = "(define (problem p) (:domain zoo) (:objects rex - pet kermit - frog rock - object)"
                        " (:init) (:goal (and)))";
  const auto lifted = test::load_task_text(domain, problem).normalized;
  auto objects_of = [&](const std::string& type) {
    for (const TypeInfo& t : lifted->types) {
      if (t.name == type) {
        std::set<std::string> names;
        for (ObjectId o : t.objects) names.insert(lifted->objects[o]);
        return names;
      }
    }
    FAIL("no type " << type);
    return std::set<std::string>{};
  };
  CHECK(objects_of("water") == std::set<std::string>{"kermit"});
  CHECK(objects_of("land") == std::set<std::string>{"kermit"});
  CHECK(objects_of("animal") == std::set<std::string>{"rex"});
  CHECK(objects_of("object") == std::set<std::string>{"rex", "kermit", "rock"});
  auto task = ground(lifted);
  CHECK(action_names(*task) == std::set<std::string>{"(feed rex)", "(feed kermit)"});
}

TEST_CASE("derived predicates become axioms by stratum, unstratifiable ones are refused") {
  const char* domain = R"(
(define (domain graph) (:requirements :derived-predicates :negative-preconditions)
  (:predicates (edge ?a ?b) (reach ?a) (start ?a) (unreachable ?a) (mark ?a))
  (:derived (reach ?a) (start ?a))
  (:derived (reach ?b) (exists (?a) (and (reach ?a) (edge ?a ?b))))
  (:derived (unreachable ?a) (not (reach ?a)))
  (:action go :parameters (?a) :precondition (unreachable ?a) :effect (mark ?a)))
)";
  const char* problem = "(define (problem p) (:domain graph) (:objects a b c)"
                        " (:init (start a) (edge a b)) (:goal (mark c)))";
  auto task = ground_text(domain, problem);
  CHECK(task->strata == 2);
  for (const GroundAxiom& ax : task->axioms) {
    const std::string head = task->fact_name(ax.head);
    CHECK(ax.stratum == (head.rfind("(unreachable", 0) == 0 ? 1u : 0u));
  }
  const char* cyclic = R"(
(define (domain bad) (:requirements :derived-predicates :negative-preconditions)
  (:predicates (p ?a) (q ?a))
  (:derived (p ?a) (not (q ?a)))
  (:derived (q ?a) (not (p ?a))))
)";
  CHECK_THROWS_AS(ground_text(cyclic, "(define (problem p) (:domain bad) (:objects a) (:init) (:goal (p a)))"),
                  GroundingError);
}

TEST_CASE("timed initial literals are sorted by time") {
  const char* domain = "(define (domain d) (:requirements :timed-initial-literals) (:predicates (open))"
                       " (:action wait :parameters () :precondition (open) :effect (and)))";
  auto task = ground_text(domain, "(define (problem p) (:domain d) (:init (at 9 (not (open))) (at 2 (open)))"
                                  " (:goal (open)))");
  REQUIRE(task->timed_literals.size() == 2);
  CHECK(task->timed_literals[0].time == 2);
  CHECK(task->timed_literals[0].positive);
  CHECK(task->timed_literals[1].time == 9);
}

// Soundness of the reachability analysis: no step of a plan VAL accepts may
// be pruned. Checked on every valid plan of the corpus.
TEST_CASE("every step of every valid corpus plan is a grounded action") {
  std::ifstream index(test::benchmarks_dir() + "/plans/index.csv");
  std::string line;
  std::getline(index, line);
  std::map<std::string, std::pair<std::shared_ptr<const GroundTask>, std::set<std::string>>> grounded;
  int plans = 0;
  while (std::getline(index, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',') && cells.size() < 4;) cells.push_back(cell);
    if (cells[3] != "valid") continue;
    auto& entry = grounded[cells[0] + "|" + cells[1]];
    if (!entry.first) {
      entry.first = ground(test::load_task(test::benchmarks_dir() + "/" + cells[0],
                                           test::benchmarks_dir() + "/" + cells[1]).normalized);
      entry.second = action_names(*entry.first);
    }
    const Plan plan = read_plan(test::read_text(test::benchmarks_dir() + "/" + cells[2]), cells[2]).plan;
    for (const PlanStep& step : plan.steps) {
      std::string name = "(" + step.action;
      for (const std::string& a : step.args) name += " " + a;
      name += ")";
      INFO(cells[2] << ": " << name);
      CHECK(entry.second.count(name) == 1);
    }
    ++plans;
  }
  CHECK(plans == 148);
}

TEST_CASE("the first problem of every IPC domain grounds") {
  for (const bench::SuiteProblem& pair : bench::load_suite(test::benchmarks_dir() + "/ipc")) {
    if (pair.number != 1) continue;
    INFO(pair.problem_file);
    auto task = ground(test::load_task(pair.domain_file, pair.problem_file).normalized);
    CHECK_FALSE(task->actions.empty());
  }
}

TEST_CASE("grounding stops with GroundingTimeout once its deadline has passed, and not before") {
  const std::string dir = test::benchmarks_dir() + "/ipc/ipc-2014/driver-log-temporal-satisficing/";
  const auto loaded = test::load_task(dir + "domain.pddl", dir + "instances/instance-3.pddl");
  GroundingOptions past;
  past.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1);
  CHECK_THROWS_AS(ground(loaded.normalized, past), GroundingTimeout);
  CHECK_THROWS_WITH(ground(loaded.normalized, past), Catch::Contains("the time limit was reached while grounding"));
  GroundingOptions future;
  future.deadline = std::chrono::steady_clock::now() + std::chrono::hours(1);
  CHECK(ground(loaded.normalized, future)->actions.size() == ground(loaded.normalized)->actions.size());
}
