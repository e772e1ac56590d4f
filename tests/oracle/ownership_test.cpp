// The reference semantics' mutex rule (oracle/ownership.h): VAL's table,
// whose verdict can depend on the order a plan lists a happening's members,
// and the symmetric rule, which judges every pair by all it claims.
#include <catch2/catch.hpp>

#include <string>

#include "oracle/judge.h"
#include "oracle/load.h"
#include "oracle/ownership.h"
#include "oracle/timed_plan.h"

using namespace alplan;

namespace {

// m deletes p and reads it in a conditional effect; n deletes p.
const char* const kDomain = R"(
(define (domain aft) (:requirements :strips :conditional-effects)
  (:predicates (p) (q))
  (:action m :parameters () :precondition (and) :effect (and (not (p)) (when (p) (q))))
  (:action n :parameters () :precondition (and) :effect (not (p)))))";
const char* const kProblem = "(define (problem a) (:domain aft) (:init (p)) (:goal (q)))";

oracle::Verdict judge(const std::string& plan, bool symmetric) {
  const oracle::LoadedTask task = oracle::load_task_text(kDomain, kProblem);
  REQUIRE(task.ok());
  oracle::JudgeOptions options;
  options.symmetric_mutex = symmetric;
  const oracle::TimedPlanRead read = oracle::read_timed_plan(plan);
  REQUIRE(read.ok());
  return oracle::Judge(task.domain, task.problem, options).judge(read.plan);
}

}  // namespace

TEST_CASE("VAL's order of claims decides a shared happening, and the symmetric rule refuses it in any order") {
  // VAL 3c7a1f3: `0: (m)`, `0: (n)` valid; `0: (n)`, `0: (m)` a mutex (n's
  // delete owns p when m's condition reads it).
  CHECK(judge("0: (m)\n0: (n)\n", false).valid());
  CHECK(judge("0: (n)\n0: (m)\n", false).failure == oracle::Failure::Mutex);
  const oracle::Verdict strict = judge("0: (m)\n0: (n)\n", true);
  CHECK(strict.failure == oracle::Failure::Mutex);
  CHECK(strict.reason.find("symmetric rule") != std::string::npos);
  CHECK(judge("0: (n)\n0: (m)\n", true).failure == oracle::Failure::Mutex);
  CHECK(judge("0: (m)\n0.001: (n)\n", true).valid());
}

TEST_CASE("the symmetric rule lets members that add, delete or increase alike share a happening") {
  oracle::Ownership o;
  CHECK(o.add_fact(0, 1));
  CHECK(o.add_fact(1, 1));
  CHECK(o.delete_fact(0, 2));
  CHECK(o.delete_fact(1, 2));
  CHECK(o.write_fluent(0, 5, true));
  CHECK(o.write_fluent(1, 5, true));
  CHECK_FALSE(o.symmetric_conflict());
  CHECK(o.read_fluent(2, 6));
  CHECK(o.write_fluent(3, 6, false) == false);  // VAL's table refuses it too
  const auto c = o.symmetric_conflict();
  REQUIRE(c);
  CHECK(c->fluent);
  CHECK(c->key == 6);
  CHECK(c->first == 2);
  CHECK(c->second == 3);
}
