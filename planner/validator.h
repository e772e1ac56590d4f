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
//
// With ValidatorOptions::report_all, validation goes on after a violation
// and lists every one it finds (ValidationResult::violations, the first
// being the one it would have stopped at):
// - steps that name no action, an unknown object, a wrong type or arity, or
//   lack a duration are all listed, and then the plan is not executed (it
//   cannot be, as written);
// - in a happening, every member's conditions are checked (per member and
//   point, the first condition that fails), then the mutex rule (the
//   happening's first clash), and the effects are applied as if all held;
//   a happening whose effects read an undefined value changes nothing;
// - the invariants of every running action are checked after each
//   happening (one violation per action and interval), trajectory
//   constraints after each state, and every unmet goal condition is listed.
// Later violations may be consequences of earlier ones (an action applied
// without its precondition leaves a state the plan's author never meant),
// as VAL's repair advice warns: fix the first and validate again.
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
  // The same, with `observer` called after each happening (a state trace).
  ValidationResult validate(const Plan& plan, const HappeningObserver& observer);
  // The same with numbers compared exactly (numeric_slack 0), whatever the
  // options: the planner's own semantics, for a plan it changed after the
  // search (planner/action_elimination.h), on the same grounded world.
  ValidationResult validate_exactly(const Plan& plan);
  // The task as the validator grounds it (open: it grows with the plans).
  const GroundTask& world() const { return *world_; }
  // A snapshot of it, with every static condition kept (the planner's task
  // drops them; a monitor must see them, since the world can change them).
  std::shared_ptr<const GroundTask> world_snapshot() const { return std::make_shared<const GroundTask>(*world_); }

 private:
  // The ground action of a step, instantiated once and cached.
  std::optional<std::size_t> instantiate_step(const PlanStep& step, std::size_t index, Violation& error);
  ValidationResult run(const Plan& plan, const HappeningObserver& observer, const ValidatorOptions& options);

  std::shared_ptr<GroundTask> world_;
  StaticFacts statics_;
  ValidatorOptions options_;
  std::map<std::pair<std::uint32_t, std::vector<ObjectId>>, std::size_t> step_actions_;
  std::unordered_map<std::string, ObjectId> objects_;
  std::unordered_map<std::string, std::uint32_t> schemas_;
};

}  // namespace alplan
