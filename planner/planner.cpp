#include "planner/planner.h"

#include "planner/pddl3_compilation.h"
#include "planner/preference_search.h"

namespace alplan {

Planner::Planner(std::shared_ptr<const GroundTask> task, PlannerOptions options,
                 std::shared_ptr<PlannerWorkspace> workspace)
    : task_(std::move(task)), options_(std::move(options)), workspace_(std::move(workspace)) {}

PlannerResult Planner::plan(const std::function<void(const FoundPlan&)>& on_plan) {
  return plan_from(initial_start(*task_), on_plan);
}

PlannerResult Planner::plan_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan) {
  // A hard `always` alone needs no compilation, but a history may have
  // broken it already.
  if (needs_compilation(*task_) || (!task_->pddl3.constraints.empty() && !start.history.empty())) {
    return PreferenceSearch(task_, options_).plan_from(start, on_plan);
  }
  return TemporalPlanner(task_, options_, workspace_).plan_from(start, on_plan);
}

}  // namespace alplan
