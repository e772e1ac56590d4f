// The planner's front door: a task with PDDL 3 beyond hard `always`
// constraints (or a history that may have broken one) goes through the
// preference search (preference_search.h), which compiles it away and plans
// the compiled tasks with the search core; every other task goes to the
// search core itself (temporal_planner.h: the POPF/OPTIC-style planner, its
// options, results and contract).
//
// Contract: plan() returns only plans our validator (VAL's semantics)
// accepts as printed; an invalid plan is a bug and is reported as
// Status::InternalError, never returned as a plan. No mutable global state:
// planners may run in several threads at once.
#pragma once

#include <functional>
#include <memory>

#include "planner/temporal_planner.h"

namespace alplan {

class Planner {
 public:
  Planner(std::shared_ptr<const GroundTask> task, PlannerOptions options,
          std::shared_ptr<PlannerWorkspace> workspace = nullptr);

  // Calls `on_plan` for every improving plan, as soon as it is found.
  PlannerResult plan(const std::function<void(const FoundPlan&)>& on_plan = {});
  PlannerResult plan_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan = {});

 private:
  std::shared_ptr<const GroundTask> task_;
  PlannerOptions options_;
  std::shared_ptr<PlannerWorkspace> workspace_;
};

}  // namespace alplan
