#include "tests/support/ground_names.h"

#include <catch2/catch.hpp>

namespace alplan::test {

ActionId action_named(const GroundTask& task, const std::string& name) {
  for (ActionId a = 0; a < task.actions.size(); ++a) {
    if (task.action_name(task.actions[a]) == name) return a;
  }
  FAIL("no ground action " << name);
  return kNoId;
}

FactId fact_named(const GroundTask& task, const std::string& name) {
  for (FactId f = 0; f < task.facts.size(); ++f) {
    if (task.fact_name(f) == name) return f;
  }
  FAIL("no fact " << name);
  return kNoId;
}

NumericVarId variable_named(const GroundTask& task, const std::string& name) {
  for (NumericVarId v = 0; v < task.initial_values.size(); ++v) {
    if (task.variable_name(v) == name) return v;
  }
  FAIL("no numeric variable " << name);
  return kNoId;
}

}  // namespace alplan::test
