// A plan validator with VAL's semantics (KCL-Planning/VAL, `Validate -t E`):
// - steps become happenings: instantaneous actions at their time, durative
//   actions as a start at t and an end at t+d, timed initial literals at
//   theirs; points within E/10 of a happening's first point join it;
// - in a happening, every condition is checked in the state before it
//   (duration constraints first, numeric comparisons with a 0.0001 slack),
//   interfering members are a mutex violation, then deletes, adds and
//   numeric updates (right-hand sides read before) are applied and derived
//   predicates re-evaluated;
// - after each happening, the invariants of the actions then running are
//   checked in the new state (the open interval, exactly);
// - the goal is checked after the last happening, timed literals included
//   (PDDL 2.2); the value is the metric in the state after the last action
//   happening, (total-time) being its time — or, without :durative-actions,
//   the number of steps and timed literals, as VAL counts it.
// The first violation stops validation and is returned as a typed record.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <unordered_map>

#include "planner/formula_evaluation.h"
#include "planner/ground_task.h"
#include "planner/instantiate.h"
#include "planner/normalized_task.h"
#include "planner/plan.h"
#include "planner/validation_result.h"
#include "planner/violation.h"

namespace alplan {

class PlanValidator {
 public:
  explicit PlanValidator(std::shared_ptr<const NormalizedTask> task, ValidatorOptions options = {});

  ValidationResult validate(const Plan& plan);
  // The task as the validator grounds it (open: it grows with the plans).
  const GroundTask& world() const { return *world_; }
  // A snapshot of it, with every static condition kept (the planner's task
  // drops them; a monitor must see them, since the world can change them).
  std::shared_ptr<const GroundTask> world_snapshot() const { return std::make_shared<const GroundTask>(*world_); }

 private:
  // The ground action of a step, instantiated once and cached.
  std::optional<std::size_t> instantiate_step(const PlanStep& step, std::size_t index, Violation& error);

  std::shared_ptr<GroundTask> world_;
  StaticFacts statics_;
  ValidatorOptions options_;
  std::map<std::pair<std::uint32_t, std::vector<ObjectId>>, std::size_t> step_actions_;
  std::unordered_map<std::string, ObjectId> objects_;
  std::unordered_map<std::string, std::uint32_t> schemas_;
};

}  // namespace alplan
