// Applying one happening's effects to an explicit state, with PDDL 2.1's
// rule that every right-hand side and effect condition is read in the state
// before the happening; deletes go before adds. The executor applies a whole
// happening at once; the monitor's world simulator one snap at a time.
#pragma once

#include "planner/formula_evaluation.h"
#include "planner/explicit_state.h"
#include "planner/ground_task.h"

namespace alplan {

// The new value of a variable; an undefined one counts as 0, as in VAL.
double updated_value(double current, pddl::AssignOperator op, double value);

// Throws EvaluationError when an effect reads an undefined value.
void apply_happening(const GroundTask& task, const HappeningEffects& effects, ExplicitState& state,
                     const EvaluationContext& context);

}  // namespace alplan
