// The classical cross-check of stable's distances (benchmarks/harness/
// stable_cross_check.h) on tasks small enough to solve by hand: its proven
// minimum is the hand-computed one, 0 where the old plan still works, and a
// plan that needs two actions at once makes the two tasks not comparable.
#include "benchmarks/harness/stable_cross_check.h"

#include <catch2/catch.hpp>

#include "pddl_parser/parser.h"
#include "planner/grounder.h"
#include "planner/plan.h"
#include "repair/reformulation.h"

using namespace alplan;
using namespace alplan::bench;

namespace {

// A walker on paths, or on a bus where one runs; durative, as the IPC
// temporal domains are.
const char* kHop = R"(
(define (domain hop)
  (:requirements :typing :durative-actions)
  (:types walker place)
  (:predicates (at ?w - walker ?p - place) (path ?a ?b - place) (bus ?a ?b - place))
  (:durative-action walk :parameters (?w - walker ?a ?b - place) :duration (= ?duration 10)
    :condition (and (at start (at ?w ?a)) (over all (path ?a ?b)))
    :effect (and (at start (not (at ?w ?a))) (at end (at ?w ?b))))
  (:durative-action ride :parameters (?w - walker ?a ?b - place) :duration (= ?duration 3)
    :condition (and (at start (at ?w ?a)) (at start (bus ?a ?b)))
    :effect (and (at start (not (at ?w ?a))) (at end (at ?w ?b)))))
)";

// Paths a-b, b-c, b-d, d-c; a bus b-c. The walker goes from a to c.
std::string hop_problem(bool path_bc) {
  return std::string(R"(
(define (problem to-c) (:domain hop)
  (:objects w - walker a b c d - place)
  (:init (at w a) (path a b) (path b d) (path d c) (bus b c))") +
         (path_bc ? " (path b c)" : "") + R"()
  (:goal (at w c)))
)";
}

std::shared_ptr<const pddl::Domain> domain_of(const char* text) {
  const auto d = pddl::parse_domain(text, "domain.pddl");
  REQUIRE(d.ok());
  return d.ast;
}

std::shared_ptr<const pddl::Problem> problem_of(const std::string& text) {
  const auto p = pddl::parse_problem(text, "problem.pddl");
  REQUIRE(p.ok());
  return p.ast;
}

const std::vector<CrossCheckStep> kWalkOverB{{"walk", {"w", "a", "b"}}, {"walk", {"w", "b", "c"}}};

}  // namespace

TEST_CASE("cross-check: the classical minimum is the hand-computed distance", "[stable-cross-check]") {
  // Path b-c closed. Keep walk a-b, forgo walk b-c, ride the bus b-c: 2.
  // Walking on over d costs 3; walk b-c cannot be kept, so nothing costs 1.
  const auto domain = domain_of(kHop);
  const auto problem = problem_of(hop_problem(false));
  const ClassicalRepairTask task = compile_classical_repair(*domain, *problem, kWalkOverB);
  REQUIRE(task.not_comparable.empty());
  const CrossCheckResult r = solve_classical_repair(task, 30.0);
  CHECK(r.status == CrossCheckStatus::Proven);
  REQUIRE(r.distance);
  CHECK(*r.distance == 2);
  CHECK(r.note.find("1 kept, 1 forgone, 1 new") == 0);
}

TEST_CASE("cross-check: an old plan that still works is at distance 0", "[stable-cross-check]") {
  const auto domain = domain_of(kHop);
  const auto problem = problem_of(hop_problem(true));
  const CrossCheckResult r = solve_classical_repair(compile_classical_repair(*domain, *problem, kWalkOverB), 30.0);
  CHECK(r.status == CrossCheckStatus::Proven);
  REQUIRE(r.distance);
  CHECK(*r.distance == 0);
}

TEST_CASE("cross-check: a running action's committed end comes before the new plan", "[stable-cross-check]") {
  // The walker is on its way to b (the walk a-b runs, its end a timed
  // literal): keep walk b-c once it has arrived, distance 0.
  const auto domain = domain_of(kHop);
  pddl::Problem problem = *problem_of(hop_problem(true));
  std::erase_if(problem.init, [](const pddl::Atom& a) { return a.name == "at"; });
  pddl::TimedInitialLiteral arrive;
  arrive.time = 4.0;
  arrive.atom.name = "at";
  for (const char* o : {"w", "b"}) arrive.atom.args.push_back(pddl::Term{pddl::Term::Kind::Name, o, {}});
  problem.timed_literals.push_back(arrive);
  const CrossCheckResult r =
      solve_classical_repair(compile_classical_repair(*domain, problem, {kWalkOverB[1]}), 30.0);
  CHECK(r.status == CrossCheckStatus::Proven);
  REQUIRE(r.distance);
  CHECK(*r.distance == 0);
  // A timed literal the problem had of its own (a window) is no committed end.
  CHECK(!compile_classical_repair(*domain, problem, {kWalkOverB[1]}, true).not_comparable.empty());
}

namespace {

// The goal needs `shine` to run while `lamp` is on: required concurrency.
const char* kLamp = R"(
(define (domain lamp)
  (:requirements :durative-actions)
  (:predicates (lit) (seen))
  (:durative-action lamp :parameters () :duration (= ?duration 10)
    :condition (and)
    :effect (and (at start (lit)) (at end (not (lit)))))
  (:durative-action look :parameters () :duration (= ?duration 2)
    :condition (over all (lit))
    :effect (at end (seen))))
)";

const char* kLampProblem = "(define (problem see) (:domain lamp) (:init) (:goal (seen)))";

}  // namespace

TEST_CASE("cross-check: a plan that needs concurrency is not comparable", "[stable-cross-check]") {
  const auto domain = domain_of(kLamp);
  const auto problem = problem_of(kLampProblem);
  const PlanReadResult read = read_plan("0.000: (lamp) [10.000]\n1.000: (look) [2.000]\n", "lamp.plan");
  REQUIRE(read.ok());
  const repair::ExecutingPlan plan = repair::bind_plan(ground(*domain, *problem), read.plan, 0.001);
  CHECK(sequential_gap(plan, 0.0).find("(look): (lit) is false") == 0);
  // The classical task cannot run look inside lamp: it has no plan, which
  // would read as a disagreement if the two were compared.
  repair::RepairRequest request;
  request.domain = domain.get();
  request.problem = problem.get();
  request.plan = &plan;
  const CrossCheckResult r = cross_check_stable(request, &plan, 10.0);
  CHECK(r.status == CrossCheckStatus::NotComparable);
  CHECK(r.note.find("stable's plan does not run one action at a time") == 0);
  CHECK(!r.distance);
}
