// A plan as the monitor executes it: ground actions of one task with their
// scheduled times. Plans come from the planner or a repair strategy as IPC
// text or plan steps; this binds them to the task they were made for.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/ground_task.h"
#include "planner/plan.h"

namespace alplan::repair {

struct ScheduledAction {
  ActionId action = 0;
  double start = 0.0;
  double duration = 0.0;  // 0 for instantaneous actions
  std::string name;       // "(move robot1 bedroom1 corridor1)"
  double end() const { return start + duration; }
};

struct ExecutingPlan {
  std::shared_ptr<const GroundTask> task;
  std::vector<ScheduledAction> steps;  // by start time
  double epsilon = 0.001;
};

// Binds plan steps to the task's ground actions by name. Throws
// std::invalid_argument naming the first step the task has no action for.
ExecutingPlan bind_plan(std::shared_ptr<const GroundTask> task, const Plan& plan, double epsilon);

// The plan's steps as the parser's plan (names, arguments, times), to
// validate or print against another task.
Plan steps_of(const ExecutingPlan& plan);

// The same plan bound to a grounding that keeps every condition: the
// planner's task drops conditions on facts no action changes (availability,
// paths), but the world can change them, so the monitor must check them.
ExecutingPlan with_all_conditions(const ExecutingPlan& plan);

// The names of the steps that start at or after `from` ("(move r a b)").
std::vector<std::string> step_names_from(const ExecutingPlan& plan, double from);

// Plan distance (Fox, Gerevini, Long & Serina, ICAPS 2006): actions in `a`
// and not in `b` plus actions in `b` and not in `a`, as multisets of ground
// actions (a step repeated twice and kept once is one change).
std::size_t plan_distance(const std::vector<std::string>& a, const std::vector<std::string>& b);
// The same between two plans' steps from `from` on: how much a repair at
// `from` changed the plan (the monitor's and the studies' stability).
std::size_t plan_distance(const ExecutingPlan& before, const ExecutingPlan& after, double from);

// The plan in the IPC format, the paper's figures' order: by start time.
std::string plan_text(const ExecutingPlan& plan);

}  // namespace alplan::repair
