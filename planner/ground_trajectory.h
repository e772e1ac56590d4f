// Grounding of PDDL 3: each trajectory constraint and preference expanded
// over the objects of its forall variables (VAL's CollectProps and
// PreferenceGoal do the same), conditions instantiated as the goal is.
#pragma once

#include <functional>
#include <vector>

#include "planner/ground_task.h"
#include "planner/instantiate.h"

namespace alplan {

// Calls `visit` once per binding of `variables` (their slots set in
// `binding`), in order of the types' objects, the first variable slowest.
void for_each_binding(const NormalizedTask& task, const std::vector<QuantifiedVariable>& variables,
                      std::vector<ObjectId>& binding, const std::function<void()>& visit);

// The ground instances of a goal's or action's preferences under `binding`
// (an action's arguments, or the goal's empty binding).
std::vector<GroundPreference> ground_preferences(const std::vector<PreferenceCondition>& preferences,
                                                 std::vector<ObjectId> binding, Instantiator& instantiate);

// The task's trajectory constraints and goal preferences, ground.
GroundTrajectory ground_trajectory(const NormalizedTask& task, Instantiator& instantiate);

}  // namespace alplan
