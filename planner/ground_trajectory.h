// Grounding of PDDL 3: each trajectory constraint and preference expanded
// over the objects of its forall variables (VAL's CollectProps and
// PreferenceGoal do the same), conditions instantiated as the goal is.
#pragma once

#include <vector>

#include "planner/ground_task.h"
#include "planner/instantiate.h"

namespace alplan {

// The task's trajectory constraints and goal preferences, ground.
GroundTrajectory ground_trajectory(const NormalizedTask& task, Instantiator& instantiate);

}  // namespace alplan
