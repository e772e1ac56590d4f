// Planning a PDDL 3 task given as text and judging the printed plan on the
// original task with the validator, apart from the compilation the planner
// used (tests of pddl3_compilation.h, pddl3_order_constraints.h and
// preference_search.h). Header-only: it uses Catch's assertions.
#pragma once

#include <catch2/catch.hpp>

#include <limits>
#include <string>

#include "planner/grounder.h"
#include "planner/planner.h"
#include "planner/validator.h"
#include "tests/support/task_loader.h"

namespace alplan::test {

// Plans `problem` on `domain`, for 20 s unless the options bound the run.
inline PlannerResult plan_texts(const char* domain, const std::string& problem, PlannerOptions options = {}) {
  const LoadedTask loaded = load_task_text(domain, problem);
  if (options.time_limit == std::numeric_limits<double>::infinity() &&
      options.node_limit == std::numeric_limits<std::size_t>::max()) {
    options.time_limit = 20.0;
  }
  return Planner(ground(loaded.normalized), options).plan();
}

// The best plan is printed, valid on the original task (constraints
// included) by the validator, and names no step the compilation added.
inline ValidationResult check_printed_plan_valid(const char* domain, const std::string& problem,
                                                 const PlannerResult& result) {
  INFO(result.message);
  REQUIRE(result.status == PlannerResult::Status::Solved);
  const LoadedTask loaded = load_task_text(domain, problem);
  PlanValidator validator(loaded.normalized);
  const ValidationResult v = validator.validate(read_plan(result.best()->text, "plan").plan);
  INFO(result.best()->text);
  CHECK(v.valid);
  CHECK(result.best()->text.find("pddl3-") == std::string::npos);
  return v;
}

}  // namespace alplan::test
