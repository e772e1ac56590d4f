// What `alplan plan` prints beside plans (issue 44): a message that holds a
// plan, the one the validator rejected, must reach a script reading plans
// from stdout as comments only.
#include <catch2/catch.hpp>

#include "planner/plan.h"

using namespace alplan;

TEST_CASE("a message holding a plan is printed as comments, never as steps") {
  const std::string message =
      "the planner produced a plan the validator rejects: (b) needs (p) at 1.001\n"
      "0.000: (a) [1.000]\n"
      "1.001: (b) [1.000]\n";
  const std::string printed = "0.000: (c) [2.000]\n" + plan_comment(message) + "; status: internal_error\n";
  const PlanReadResult read = read_plan(printed, "stdout");
  REQUIRE(read.ok());
  REQUIRE(read.plan.steps.size() == 1);
  CHECK(read.plan.steps[0].action == "c");
  CHECK(plan_comment(message) ==
        "; the planner produced a plan the validator rejects: (b) needs (p) at 1.001\n"
        "; 0.000: (a) [1.000]\n"
        "; 1.001: (b) [1.000]\n");
}

TEST_CASE("a one-line message is one comment line, an empty one an empty comment") {
  CHECK(plan_comment("no plan exists") == "; no plan exists\n");
  CHECK(plan_comment("") == "; \n");
  CHECK(plan_comment("a\n\nb") == "; a\n; \n; b\n");
}
