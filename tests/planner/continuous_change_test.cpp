// Linear continuous change (PDDL 2.1 level 4, planner/continuous_change.h):
// the planner schedules with a linear program where values change with
// time, and the validator checks invariants over the intervals between
// happenings, as VAL does.
#include <catch2/catch.hpp>

#include "planner/grounder.h"
#include "planner/planner.h"
#include "planner/validator.h"
#include "tests/support/task_loader.h"
#include "tests/support/test_paths.h"

using namespace alplan;
using Status = PlannerResult::Status;

namespace {

// COLIN's linear generator: it burns 1 fuel per time unit for 100 units and
// holds only 60; each tank pours at its rate for 10 units while it runs,
// never over capacity.
const char* kGenerator = R"(
(define (domain generator)
  (:requirements :typing :durative-actions :fluents :continuous-effects :duration-inequalities)
  (:types generator tank)
  (:predicates (generator-ran ?g - generator) (available ?t - tank) (running ?g - generator))
  (:functions (fuel ?g - generator) (capacity ?g - generator) (rate ?t - tank))
  (:durative-action generate
    :parameters (?g - generator)
    :duration (= ?duration 100)
    :condition (over all (>= (fuel ?g) 0))
    :effect (and (at start (running ?g)) (at end (not (running ?g)))
                 (decrease (fuel ?g) (* #t 1))
                 (at end (generator-ran ?g))))
  (:durative-action refuel
    :parameters (?g - generator ?t - tank)
    :duration (= ?duration 10)
    :condition (and (at start (available ?t)) (over all (running ?g))
                    (over all (<= (fuel ?g) (capacity ?g))))
    :effect (and (at start (not (available ?t)))
                 (increase (fuel ?g) (* #t (rate ?t))))))
)";
const char* kGeneratorProblem = R"(
(define (problem gen1) (:domain generator)
  (:objects g - generator t1 t2 - tank)
  (:init (= (fuel g) 60) (= (capacity g) 60) (available t1) (available t2) (= (rate t1) 3) (= (rate t2) 3))
  (:goal (generator-ran g))
  (:metric minimize (total-time)))
)";

// A robot must cross a 10-unit corridor draining 2 per unit and keep 5 in
// reserve; it starts with 10 beside a dock that charges 5 per unit, for as
// long as it likes up to full.
const char* kBattery = R"(
(define (domain battery)
  (:requirements :typing :durative-actions :fluents :continuous-effects :duration-inequalities)
  (:types robot place)
  (:predicates (at ?r - robot ?p - place) (dock ?p - place) (link ?a ?b - place))
  (:functions (battery ?r - robot) (capacity ?r - robot) (reserve ?r - robot) (length ?a ?b - place))
  (:durative-action move
    :parameters (?r - robot ?a ?b - place)
    :duration (= ?duration (length ?a ?b))
    :condition (and (at start (at ?r ?a)) (over all (link ?a ?b))
                    (over all (>= (battery ?r) (reserve ?r))))
    :effect (and (at start (not (at ?r ?a))) (at end (at ?r ?b))
                 (decrease (battery ?r) (* #t 2))))
  (:durative-action charge
    :parameters (?r - robot ?p - place)
    :duration (and (>= ?duration 0.5) (<= ?duration (/ (- (capacity ?r) (battery ?r)) 5)))
    :condition (and (over all (at ?r ?p)) (at start (dock ?p)))
    :effect (increase (battery ?r) (* #t 5))))
)";
const char* kBatteryProblem = R"(
(define (problem cross) (:domain battery)
  (:objects r - robot a b - place)
  (:init (at r a) (dock a) (link a b) (= (length a b) 10)
         (= (battery r) 10) (= (capacity r) 100) (= (reserve r) 5))
  (:goal (at r b))
  (:metric minimize (total-time)))
)";

// A goal on a changing value: fill a tank to at least 50 at 2 per unit.
const char* kTank = R"(
(define (domain tank)
  (:requirements :durative-actions :fluents :continuous-effects :duration-inequalities)
  (:predicates (idle))
  (:functions (level) (capacity))
  (:durative-action fill
    :parameters ()
    :duration (and (>= ?duration 1) (<= ?duration 100))
    :condition (and (at start (idle)) (over all (<= (level) (capacity))))
    :effect (and (at start (not (idle))) (at end (idle)) (increase (level) (* #t 2)))))
)";
const char* kTankProblem = R"(
(define (problem fill50) (:domain tank)
  (:init (idle) (= (level) 0) (= (capacity) 80))
  (:goal (>= (level) 50))
  (:metric minimize (total-time)))
)";

PlannerResult plan_text(const char* domain, const char* problem) {
  PlannerOptions options;
  options.time_limit = 20.0;
  return Planner(ground(test::load_task_text(domain, problem).normalized), options).plan();
}

ValidationResult validate_text(const char* domain, const char* problem, const std::string& plan) {
  const test::LoadedTask task = test::load_task_text(domain, problem);
  const PlanReadResult read = read_plan(plan, "plan");
  REQUIRE(read.ok());
  return PlanValidator(task.normalized).validate(read.plan);
}

const PlanStep& step_named(const Plan& plan, const std::string& action, std::size_t nth = 0) {
  for (const PlanStep& s : plan.steps) {
    if (s.action == action && nth-- == 0) return s;
  }
  FAIL("no " << action << " in the plan");
  return plan.steps.front();
}

}  // namespace

TEST_CASE("continuous change: the generator is refuelled while it runs and never over capacity") {
  const PlannerResult r = plan_text(kGenerator, kGeneratorProblem);
  REQUIRE(r.status == Status::Solved);
  const Plan& plan = r.best()->plan;
  INFO(r.best()->text);
  CHECK(r.best()->validation.valid);
  const PlanStep& generate = step_named(plan, "generate");
  // 100 units of burning from a 60 tank: both tanks, each started once the
  // level has fallen 20 below capacity (it rises by 2 per unit while pouring).
  // The two may overlap: whatever the first's start, the level at the
  // second's end is 110 - its start (from the generator's start), so it
  // cannot start before 50.
  const PlanStep& first = step_named(plan, "refuel", 0);
  const PlanStep& second = step_named(plan, "refuel", 1);
  CHECK(*first.time >= *generate.time + 20.0 - 1e-6);
  CHECK(*second.time >= *generate.time + 50.0 - 1e-6);
  CHECK(*second.duration + *second.time <= *generate.time + 100.0 + 1e-6);
  CHECK(r.best()->validation.makespan == Approx(100.0));
}

TEST_CASE("continuous change: a charge lasts as long as the move after it needs") {
  const PlannerResult r = plan_text(kBattery, kBatteryProblem);
  REQUIRE(r.status == Status::Solved);
  INFO(r.best()->text);
  CHECK(r.best()->validation.valid);
  // The move drains 20 and must end at 5 or more: 15 more than the 10 held,
  // three units of charging at 5 per unit.
  const PlanStep& charge = step_named(r.best()->plan, "charge");
  CHECK(*charge.duration >= 3.0 - 1e-6);
  CHECK(*charge.duration <= 3.0 + 1e-3);
}

TEST_CASE("continuous change: a numeric goal on a changing value fixes the flexible duration") {
  const PlannerResult r = plan_text(kTank, kTankProblem);
  REQUIRE(r.status == Status::Solved);
  INFO(r.best()->text);
  CHECK(r.best()->validation.valid);
  CHECK(*step_named(r.best()->plan, "fill").duration == Approx(25.0).margin(1e-3));
}

TEST_CASE("continuous change: the validator checks invariants between happenings") {
  SECTION("the plan with both tanks poured late enough is valid") {
    const ValidationResult v =
        validate_text(kGenerator, kGeneratorProblem, "0: (generate g) [100]\n20: (refuel g t1) [10]\n50: (refuel g t2) [10]\n");
    REQUIRE(v.valid);
    CHECK(v.value == Approx(100.0));
  }
  SECTION("without refuelling the fuel runs out before the end") {
    const ValidationResult v = validate_text(kGenerator, kGeneratorProblem, "0: (generate g) [100]\n");
    REQUIRE_FALSE(v.valid);
    CHECK(v.violation->kind == Violation::Kind::UnsatisfiedInvariant);
    CHECK(v.violation->condition.find("fuel") != std::string::npos);
  }
  SECTION("pouring at once overflows the tank within the refuel's interval") {
    const ValidationResult v = validate_text(kGenerator, kGeneratorProblem,
                                             "0: (generate g) [100]\n0.001: (refuel g t1) [10]\n50: (refuel g t2) [10]\n");
    REQUIRE_FALSE(v.valid);
    CHECK(v.violation->kind == Violation::Kind::UnsatisfiedInvariant);
    CHECK(v.violation->condition == "(<= (fuel g) 60)");  // the static capacity, grounded
  }
  SECTION("a charge too short leaves the move below its reserve") {
    const ValidationResult v =
        validate_text(kBattery, kBatteryProblem, "0: (charge r a) [2]\n2.001: (move r a b) [10]\n");
    REQUIRE_FALSE(v.valid);
    CHECK(v.violation->kind == Violation::Kind::UnsatisfiedInvariant);
  }
  SECTION("a charge past full breaks its duration constraint") {
    const ValidationResult v =
        validate_text(kBattery, kBatteryProblem, "0: (charge r a) [20]\n20.001: (move r a b) [10]\n");
    REQUIRE_FALSE(v.valid);
    CHECK(v.violation->kind == Violation::Kind::DurationViolation);
  }
}

TEST_CASE("continuous change: what is not linear is refused by name and place") {
  auto refusal = [](const std::string& effect) {
    const std::string domain = std::string(R"(
(define (domain d) (:requirements :durative-actions :fluents :continuous-effects)
  (:predicates (p)) (:functions (x) (y))
  (:durative-action a :parameters () :duration (= ?duration 1)
    :condition (at start (p)) :effect (and (at end (p)) )") + effect + ")))";
    const char* problem = "(define (problem q) (:domain d) (:init (p) (= (x) 0) (= (y) 1)) (:goal (p)))";
    PlannerOptions options;
    const PlannerResult r = Planner(ground(test::load_task_text(domain, problem).normalized), options).plan();
    CHECK(r.status == Status::Unsupported);
    return r.message;
  };
  CHECK_THAT(refusal("(increase (x) (* #t #t))"), Catch::Contains("non-linear"));
  CHECK_THAT(refusal("(assign (x) (* #t 2))"), Catch::Contains("continuous change by assign"));
  CHECK_THAT(refusal("(increase (x) (* #t ?duration))"), Catch::Contains("depends on ?duration"));
  CHECK_THAT(refusal("(increase (x) (* #t (y))) (increase (y) (* #t 1))"), Catch::Contains("itself changes"));
}

namespace {

std::string continuous_file(const std::string& domain, const std::string& file) {
  return test::source_dir() + "/domains/continuous/" + domain + "/" + file;
}

const char* const kContinuousDomains[] = {"generator", "robot-battery", "rover-energy", "tank"};

}  // namespace

TEST_CASE("continuous domains: the hand-written plans of every problem are valid") {
  for (const char* domain : kContinuousDomains) {
    for (int n = 1; n <= 4; ++n) {
      const std::string problem = "p0" + std::to_string(n);
      INFO(domain << " " << problem);
      const test::LoadedTask task =
          test::load_task(continuous_file(domain, "domain.pddl"), continuous_file(domain, problem + ".pddl"));
      const PlanReadResult plan = read_plan(test::read_text(continuous_file(domain, problem + ".plan")), problem + ".plan");
      REQUIRE(plan.ok());
      const ValidationResult v = PlanValidator(task.normalized).validate(plan.plan);
      CHECK(v.valid);
    }
  }
}

// The problems solved in about a second (benchmarks/README.md has the
// rest); generator p04 and rover-energy p03 need the resource balance
// (planner/resource_shortfall.h): without it they time out. Limited by
// nodes, not time: generator p04 (132 expansions, 1,384 evaluations, each
// scheduled by a linear program) took over 30 s under AddressSanitizer on
// a slower CI machine, and the run is the same on any machine this way.
TEST_CASE("continuous domains: the planner solves the smaller problems, validly") {
  const std::pair<const char*, const char*> solved[] = {
      {"generator", "p01"},    {"generator", "p02"},    {"generator", "p03"},    {"generator", "p04"},
      {"robot-battery", "p01"}, {"rover-energy", "p01"}, {"rover-energy", "p02"}, {"rover-energy", "p03"},
      {"tank", "p01"},         {"tank", "p02"}};
  for (const auto& [domain, problem] : solved) {
    INFO(domain << " " << problem);
    const test::LoadedTask task = test::load_task(continuous_file(domain, "domain.pddl"),
                                                  continuous_file(domain, std::string(problem) + ".pddl"));
    PlannerOptions options;
    options.time_limit = 600.0;
    options.node_limit = 5000;
    const PlannerResult r = Planner(ground(task.normalized), options).plan();
    REQUIRE(r.status == Status::Solved);
    CHECK(r.best()->validation.valid);
  }
}

// Type-based exploration alone does not solve robot-battery p04 in 60 s
// (3,539 expansions; plain GBFS needs 907): its random expansions put
// children in the greedy queue that lead it astray. EHC's fallback keeps a
// plain GBFS beside the typed ones, which found the plan; since numeric
// supporters are chosen by direction (numeric_intervals.h) the novelty-ordered
// GBFS finds one first. Limited by nodes, not time, so the run is the same
// on any machine.
TEST_CASE("continuous domains: EHC's fallback solves robot-battery p04") {
#if defined(__SANITIZE_ADDRESS__)
  // About 4,000 expansions, each scheduled by a linear program: minutes
  // under the sanitizers. The same fallback runs there in planner_test.cpp.
  WARN("too slow under AddressSanitizer");
  return;
#endif
  const test::LoadedTask task =
      test::load_task(continuous_file("robot-battery", "domain.pddl"), continuous_file("robot-battery", "p04.pddl"));
  PlannerOptions options;
  options.node_limit = 100000;
  const PlannerResult r = Planner(ground(task.normalized), options).plan();
  REQUIRE(r.status == Status::Solved);
  CHECK(r.best()->validation.valid);
  CHECK(r.best()->engine.rfind("gbfs", 0) == 0);
}
