// The reference semantics' count of over-all preferences (issue 44)
// against tests/support/over_all_preference_cases.h, counted by hand.
#include <catch2/catch.hpp>

#include "oracle/judge.h"
#include "oracle/load.h"
#include "oracle/timed_plan.h"
#include "tests/support/over_all_preference_cases.h"

using namespace alplan;

TEST_CASE("the reference semantics counts every violated over-all preference instance once per step") {
  const oracle::LoadedTask task =
      oracle::load_task_text(test::kOverAllPreferenceDomain, test::kOverAllPreferenceProblem);
  REQUIRE(task.ok());
  for (const test::OverAllPreferenceCase& c : test::over_all_preference_cases()) {
    INFO(c.what);
    const oracle::TimedPlanRead read = oracle::read_timed_plan(c.plan);
    REQUIRE(read.ok());
    const oracle::Verdict v = oracle::Judge(task.domain, task.problem).judge(read.plan);
    INFO(v.reason);
    REQUIRE(v.valid());
    for (const auto& [name, count] : c.violations) {
      INFO(name);
      const auto it = v.preference_violations.find(name);
      CHECK((it == v.preference_violations.end() ? 0.0 : it->second) == count);
    }
    CHECK(v.value == Approx(c.value));
  }
}
