// VAL's interference rule for happenings at one time with derived
// predicates: a condition on a derived fact reads everything it is derived
// from, so a happening that deletes one of those at that time is a mutex
// (VAL: "Mutex violation: (a) (deletes (f))"); the planner separates them.
#include <catch2/catch.hpp>

#include <algorithm>

#include "planner/derived_support.h"
#include "planner/grounder.h"
#include "planner/planner.h"
#include "planner/task_index.h"
#include "planner/validator.h"
#include "tests/support/ground_names.h"
#include "tests/support/task_loader.h"
#include "tests/support/test_paths.h"

using namespace alplan;

namespace {

const char* const kDomain = R"(
(define (domain derived-mutex) (:requirements :strips :derived-predicates)
  (:predicates (f) (g) (done-a) (done-b) (d))
  (:derived (d) (and (f) (g)))
  (:action a :parameters () :precondition (g) :effect (and (not (f)) (done-a)))
  (:action b :parameters () :precondition (d) :effect (done-b))))";
const char* const kProblem = "(define (problem p) (:domain derived-mutex) (:init (f) (g)) (:goal (and (done-a) (done-b))))";

// PSR's shape: a derived fact fed through a cycle of rules.
const char* const kCycle = R"(
(define (domain fed) (:requirements :strips :derived-predicates)
  (:predicates (closed1) (closed2) (fed1) (fed2) (source))
  (:derived (fed1) (or (source) (and (fed2) (closed1))))
  (:derived (fed2) (and (fed1) (closed2)))
  (:action open1 :parameters () :precondition (closed1) :effect (not (closed1)))
  (:action open2 :parameters () :precondition (closed2) :effect (not (closed2)))
  (:action cut :parameters () :precondition (source) :effect (not (source)))))";

ValidationResult validate(const std::string& plan) {
  const test::LoadedTask loaded = test::load_task_text(kDomain, kProblem);
  PlanValidator validator(loaded.normalized);
  return validator.validate(read_plan(plan, "plan").plan);
}

}  // namespace

TEST_CASE("deleting what a derived precondition reads at the same time is a mutex") {
  const ValidationResult same_time = validate("0.000: (b)\n0.000: (a)\n");
  REQUIRE_FALSE(same_time.valid);
  CHECK(same_time.violation->kind == Violation::Kind::MutexViolation);
  CHECK(same_time.violation->message().find("(f)") != std::string::npos);
  CHECK(validate("0.000: (b)\n0.001: (a)\n").valid);
}

TEST_CASE("the planner separates a writer from a reader of what a derived fact depends on") {
  const test::LoadedTask loaded = test::load_task_text(kDomain, kProblem);
  const PlannerResult result = Planner(ground(loaded.normalized), PlannerOptions{}).plan();
  REQUIRE(result.status == PlannerResult::Status::Solved);
  CHECK(result.best()->validation.valid);
  CHECK(result.best()->plan.steps.size() == 2);
  CHECK(*result.best()->plan.steps[0].time != *result.best()->plan.steps[1].time);
}

TEST_CASE("the support of a derived fact on a cycle of rules is the whole cycle's") {
  const test::LoadedTask loaded =
      test::load_task_text(kCycle, "(define (problem p) (:domain fed) (:init (closed1) (closed2) (source)) (:goal (fed2)))");
  const std::shared_ptr<const GroundTask> task = ground(loaded.normalized);
  DerivedSupport support(*task);
  auto names = [&](FactId derived) {
    std::vector<std::string> out;
    for (FactId f : support.of(derived).facts) out.push_back(task->fact_name(f));
    return out;
  };
  // Asked about fed2 first, then fed1 (on fed2's stack when the memo was
  // written before): both depend on both switches and the source.
  const std::vector<std::string> all{"(closed1)", "(closed2)", "(source)"};
  CHECK(names(test::fact_named(*task, "(fed2)")) == all);
  CHECK(names(test::fact_named(*task, "(fed1)")) == all);
}

TEST_CASE("what a derived predicate reads, by predicate, goes through every rule it mentions") {
  const test::LoadedTask loaded =
      test::load_task_text(kCycle, "(define (problem p) (:domain fed) (:init (closed1) (closed2) (source)) (:goal (fed2)))");
  const NormalizedTask& lifted = *loaded.normalized;
  const LiftedDerivedReads reads(lifted);
  auto names = [&](const std::string& derived) {
    std::vector<std::string> out;
    for (std::size_t p = 0; p < lifted.predicates.size(); ++p) {
      if (lifted.predicates[p].name != derived) continue;
      for (PredicateId q : reads.predicates(static_cast<PredicateId>(p))) out.push_back(lifted.predicates[q].name);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const std::vector<std::string> all{"closed1", "closed2", "source"};
  CHECK(names("fed1") == all);
  CHECK(names("fed2") == all);
  CHECK(names("closed1").empty());
}

// PSR instance 10 (shared suite, instances 6-10 run as a test set): the
// planner's grounder has no axiom for (unsafe cb3 side2), the validator's
// has several, through which (affected cb3) reads (closed sd18); the
// planner put (open sd18) and (open sd17) at one time, a plan its validator
// rejected. The index orders by what the lifted rules read.
TEST_CASE("on PSR the planner orders a switch's opening after every reader of the breakers' derived state") {
  const std::string dir = test::benchmarks_dir() + "/ipc/ipc-2004/psr-middle-derived-predicates-adl/";
  const test::LoadedTask loaded = test::load_task(dir + "domain.pddl", dir + "instances/instance-10.pddl");
  const std::shared_ptr<const GroundTask> task = ground(loaded.normalized);
  const TaskIndex index(task);
  const Footprint& reader = index.footprint({SnapKind::Instant, test::action_named(*task, "(open sd17)")});
  const Footprint& writer = index.footprint({SnapKind::Instant, test::action_named(*task, "(open sd18)")});
  const FactId closed18 = test::fact_named(*task, "(closed sd18)");
  CHECK(std::binary_search(reader.reads.begin(), reader.reads.end(), closed18));
  CHECK(std::binary_search(writer.writes.begin(), writer.writes.end(), closed18));
}
