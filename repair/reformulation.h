// Reformulating the planning problem from an observed state (the paper's
// Section 6.3, step 3c): the objects known so far (new ones included), the
// observed atoms and values as the initial state, the timed initial literals
// still to come, the goal and the metric. Actions still running are
// committed: their ends become timed initial literals at the world's
// estimate of when they end. The result is an ordinary PDDL problem, so the
// same text can go to a planner in another process.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/planner.h"
#include "repair/executing_plan.h"
#include "repair/world.h"
#include "repair/world_state.h"

namespace alplan::repair {

// `shift` is subtracted from every time (an external planner starts at 0;
// the in-process one plans in the task's own time from `now`).
pddl::Problem reformulate(const pddl::Domain& domain, const pddl::Problem& base, const WorldState& observed,
                          const std::vector<ActionInProgress>& in_progress, double now, double shift = 0.0);

struct PlanningOutcome {
  std::optional<ExecutingPlan> plan;
  PlannerResult::Status status = PlannerResult::Status::LimitReached;
  std::string message;
  double seconds = 0.0;  // grounding and search
};

// Grounds the problem and plans from `now` with the in-process planner.
PlanningOutcome plan_in_process(const pddl::Domain& domain, const pddl::Problem& problem, double now,
                                const PlannerOptions& options);

// The object a name denotes in the problem, with its declared type.
std::optional<std::string> object_type(const pddl::Problem& problem, const std::string& object);

}  // namespace alplan::repair
