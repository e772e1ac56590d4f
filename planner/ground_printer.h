// Ground structures written as PDDL, for violation records, explanations and
// `alplan ground --dump`.
#pragma once

#include <iosfwd>
#include <string>

#include "planner/ground_task.h"

namespace alplan {

std::string write_expression(const GroundTask& task, const GroundExpression& expression);
std::string write_comparison(const GroundTask& task, const GroundComparison& comparison);
std::string write_formula(const GroundTask& task, const GroundFormula& formula);
std::string write_condition(const GroundTask& task, const ConditionSet& condition);
std::string write_effects(const GroundTask& task, const HappeningEffects& effects);

// The whole task, readably: facts, variables, actions, axioms, TILs, goal.
void dump(const GroundTask& task, std::ostream& out);

}  // namespace alplan
