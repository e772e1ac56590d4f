// Greedy action elimination (planner/action_elimination.h): an action no
// condition and no goal needs goes, with the steps that only undid it; the
// rest is rescheduled on its causal order, and nothing the caller does not
// accept is ever returned.
#include "planner/action_elimination.h"

#include <catch2/catch.hpp>

#include "planner/grounder.h"
#include "planner/task_index.h"
#include "tests/support/ground_names.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

const char* const kCourier = R"(
(define (domain courier) (:requirements :strips :durative-actions)
  (:predicates (at-a) (at-b) (holding) (on-table) (delivered) (honked))
  (:durative-action drive :parameters () :duration (= ?duration 5)
    :condition (at start (at-a)) :effect (and (at start (not (at-a))) (at end (at-b))))
  (:durative-action honk :parameters () :duration (= ?duration 10)
    :effect (at end (honked)))
  (:durative-action put :parameters () :duration (= ?duration 1)
    :condition (at start (holding)) :effect (and (at start (not (holding))) (at end (on-table))))
  (:durative-action take :parameters () :duration (= ?duration 1)
    :condition (at start (on-table)) :effect (and (at start (not (on-table))) (at end (holding))))
  (:durative-action deliver :parameters () :duration (= ?duration 1)
    :condition (and (at start (at-b)) (at start (holding))) :effect (at end (delivered))))
)";

struct Fixture {
  std::shared_ptr<const GroundTask> task = ground(
      test::load_task_text(kCourier,
                           "(define (problem p) (:domain courier) (:init (at-a) (holding)) (:goal (delivered)))")
          .normalized);
  TaskIndex index{task};
  SearchState start{static_cast<std::uint32_t>(task->facts.size()), task->initial_values};
  ActionId drive = test::action_named(*task, "(drive)");
  ActionId honk = test::action_named(*task, "(honk)");
  ActionId put = test::action_named(*task, "(put)");
  ActionId take = test::action_named(*task, "(take)");
  ActionId deliver = test::action_named(*task, "(deliver)");

  Fixture() {
    for (FactId f : task->initial_facts) start.set_fact(f, true);
  }

  // Appends a durative action's start at `at` and its end `d` later, in
  // the order of the calls (ends placed by the caller's order of calls).
  static void add(Solution& s, ActionId a, double at, double d) {
    const std::uint32_t begin = static_cast<std::uint32_t>(s.steps.size());
    s.steps.push_back(StepRecord{{SnapKind::Start, a}, kNoId, d, d});
    s.times.push_back(at);
    s.steps.push_back(StepRecord{{SnapKind::End, a}, begin, d, d});
    s.times.push_back(at + d);
  }

  // honk beside the drive (nothing needs it), a put and the take that
  // undoes it while driving, then the delivery.
  Solution plan() const {
    Solution s;
    add(s, honk, 0.0, 10.0);
    add(s, drive, 0.0, 5.0);
    add(s, put, 0.0, 1.0);
    add(s, take, 1.001, 1.0);
    add(s, deliver, 5.001, 1.0);
    s.makespan = 10.0;
    return s;
  }

  bool has(const Solution& s, ActionId a) const {
    for (const StepRecord& r : s.steps) {
      if (r.snap.kind != SnapKind::TimedLiteral && r.snap.index == a) return true;
    }
    return false;
  }
};

}  // namespace

TEST_CASE("removing an action takes the steps that lose their support with it, and renumbers the ends") {
  const Fixture f;
  const Solution plan = f.plan();
  // put, by its end (step 5): take's condition (on-table) has no achiever left.
  const std::optional<std::vector<bool>> removed = removal_set(*f.task, f.start, plan, 5);
  REQUIRE(removed);
  CHECK(*removed == std::vector<bool>{false, false, false, false, true, true, true, true, false, false});
  const Solution fewer = without_steps(plan, *removed);
  REQUIRE(fewer.steps.size() == 6);
  CHECK(fewer.steps[5].start_step == 4);  // deliver's end, renumbered
  CHECK(fewer.times[4] == Approx(5.001));
  // drive cannot go: deliver, the goal's only achiever, would go with it,
  // and a removal that loses the goal is no candidate.
  CHECK_FALSE(removal_set(*f.task, f.start, plan, 3));
}

TEST_CASE("an action nothing needs goes, and the pair that only undid itself too, and the plan is rescheduled") {
  const Fixture f;
  const DeorderingInput input{f.index, f.start, 0.0, 0.001};
  // The caller's judgement, standing in for validation: the goal needs deliver.
  const std::optional<Solution> result =
      eliminate_actions(input, f.plan(), [&](const Solution& candidate) { return f.has(candidate, f.deliver); });
  REQUIRE(result);
  CHECK_FALSE(f.has(*result, f.honk));
  CHECK_FALSE(f.has(*result, f.put));
  CHECK_FALSE(f.has(*result, f.take));
  CHECK(f.has(*result, f.drive));
  CHECK(result->steps.size() == 4);
  CHECK(result->makespan == Approx(6.001));
}

TEST_CASE("nothing the caller refuses is returned") {
  const Fixture f;
  const DeorderingInput input{f.index, f.start, 0.0, 0.001};
  std::size_t offered = 0;
  CHECK_FALSE(eliminate_actions(input, f.plan(), [&](const Solution&) {
    ++offered;
    return false;
  }));
  CHECK(offered > 0);
}
