// The validator's count of over-all preferences (issue 44) against
// tests/support/over_all_preference_cases.h, counted by hand.
#include <catch2/catch.hpp>

#include "planner/validator.h"
#include "tests/support/over_all_preference_cases.h"
#include "tests/support/task_loader.h"

using namespace alplan;

TEST_CASE("the validator counts every violated over-all preference instance once per step") {
  const test::LoadedTask task = test::load_task_text(test::kOverAllPreferenceDomain, test::kOverAllPreferenceProblem);
  for (const test::OverAllPreferenceCase& c : test::over_all_preference_cases()) {
    INFO(c.what);
    PlanValidator validator(task.normalized);
    const PlanReadResult plan = read_plan(c.plan, "plan");
    REQUIRE(plan.ok());
    const ValidationResult r = validator.validate(plan.plan);
    INFO((r.valid ? std::string("valid") : r.violation->message()));
    REQUIRE(r.valid);
    for (const auto& [name, count] : c.violations) {
      INFO(name);
      CHECK(r.preference_violations.at(name) == count);
    }
    CHECK(r.value == Approx(c.value));
  }
}
