#include "repair/executing_plan.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>

#include "planner/validator.h"

namespace alplan::repair {

ExecutingPlan bind_plan(std::shared_ptr<const GroundTask> task, const Plan& plan, double epsilon) {
  std::unordered_map<std::string, ActionId> by_name;
  for (ActionId a = 0; a < task->actions.size(); ++a) by_name.emplace(task->action_name(task->actions[a]), a);
  ExecutingPlan bound;
  bound.epsilon = epsilon;
  for (const PlanStep& step : plan.steps) {
    std::string name = "(" + step.action;
    for (const std::string& arg : step.args) name += " " + arg;
    name += ")";
    auto it = by_name.find(name);
    if (it == by_name.end()) throw std::invalid_argument("the task has no action " + name);
    ScheduledAction s;
    s.action = it->second;
    s.start = step.time.value_or(0.0);
    s.duration = step.duration.value_or(0.0);
    s.name = std::move(name);
    bound.steps.push_back(std::move(s));
  }
  std::stable_sort(bound.steps.begin(), bound.steps.end(),
                   [](const ScheduledAction& a, const ScheduledAction& b) { return a.start < b.start; });
  bound.task = std::move(task);
  return bound;
}

ExecutingPlan with_all_conditions(const ExecutingPlan& plan) {
  Plan steps;
  for (const ScheduledAction& s : plan.steps) {
    PlanStep step;
    step.time = s.start;
    const std::size_t space = s.name.find(' ');
    step.action = s.name.substr(1, (space == std::string::npos ? s.name.size() - 1 : space) - 1);
    const GroundAction& a = plan.task->actions[s.action];
    for (ObjectId o : a.args) step.args.push_back(plan.task->lifted->objects[o]);
    if (a.durative) step.duration = s.duration;
    steps.steps.push_back(std::move(step));
  }
  // Validation from the task's initial state says nothing about a plan made
  // from a later state; it is run only to ground the plan's steps in full.
  PlanValidator validator(plan.task->lifted, ValidatorOptions{plan.epsilon, false});
  validator.validate(steps);
  return bind_plan(validator.world_snapshot(), steps, plan.epsilon);
}

std::string plan_text(const ExecutingPlan& plan) {
  std::string out;
  char buffer[64];
  for (const ScheduledAction& s : plan.steps) {
    std::snprintf(buffer, sizeof buffer, "%.3f: ", s.start);
    out += buffer + s.name;
    if (plan.task->actions[s.action].durative) {
      std::snprintf(buffer, sizeof buffer, " [%.3f]", s.duration);
      out += buffer;
    }
    out += "\n";
  }
  return out;
}

}  // namespace alplan::repair
