// Ground actions, facts and numeric variables of a grounded task by their
// printed names ("(move r a b)", "(at r a)", "(battery r)"), for tests that
// set up states and running actions by hand. A name the task lacks fails the
// running test.
#pragma once

#include <string>

#include "planner/ground_task.h"

namespace alplan::test {

ActionId action_named(const GroundTask& task, const std::string& name);
FactId fact_named(const GroundTask& task, const std::string& name);
NumericVarId variable_named(const GroundTask& task, const std::string& name);

}  // namespace alplan::test
