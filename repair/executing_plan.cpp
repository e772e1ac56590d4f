#include "repair/executing_plan.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>

#include "planner/diverse_plans.h"
#include "planner/validator.h"

namespace alplan::repair {

namespace {

std::string step_name(const PlanStep& step) {
  std::string name = "(" + step.action;
  for (const std::string& arg : step.args) name += " " + arg;
  return name + ")";
}

// The ground action of every step, by schema and argument ids: one pass
// over the task's actions comparing integers. (Naming every action of the
// task to look up a dozen steps was 3% of a repair.)
std::vector<ActionId> step_actions(const GroundTask& task, const Plan& plan) {
  const NormalizedTask& lifted = *task.lifted;
  std::unordered_map<std::string, std::uint32_t> schemas;
  for (std::uint32_t a = 0; a < lifted.actions.size(); ++a) schemas.emplace(lifted.actions[a].name, a);
  std::unordered_map<std::string, ObjectId> objects;
  for (ObjectId o = 0; o < lifted.objects.size(); ++o) objects.emplace(lifted.objects[o], o);
  struct Wanted {
    std::uint32_t schema = kNoId;
    std::vector<ObjectId> args;
    ActionId action = kNoId;
  };
  std::vector<Wanted> wanted(plan.steps.size());
  for (std::size_t i = 0; i < plan.steps.size(); ++i) {
    const PlanStep& step = plan.steps[i];
    const auto schema = schemas.find(step.action);
    if (schema == schemas.end()) continue;
    wanted[i].schema = schema->second;
    for (const std::string& arg : step.args) {
      const auto object = objects.find(arg);
      wanted[i].args.push_back(object == objects.end() ? kNoId : object->second);
    }
  }
  std::vector<ActionId> found(plan.steps.size(), kNoId);
  for (ActionId a = 0; a < task.actions.size(); ++a) {
    const GroundAction& action = task.actions[a];
    for (Wanted& w : wanted) {
      if (w.action == kNoId && w.schema == action.schema && w.args == action.args) w.action = a;
    }
  }
  for (std::size_t i = 0; i < plan.steps.size(); ++i) {
    if (wanted[i].action == kNoId) throw std::invalid_argument("the task has no action " + step_name(plan.steps[i]));
    found[i] = wanted[i].action;
  }
  return found;
}

}  // namespace

ExecutingPlan bind_plan(std::shared_ptr<const GroundTask> task, const Plan& plan, double epsilon) {
  const std::vector<ActionId> actions = step_actions(*task, plan);
  ExecutingPlan bound;
  bound.epsilon = epsilon;
  for (std::size_t i = 0; i < plan.steps.size(); ++i) {
    const PlanStep& step = plan.steps[i];
    ScheduledAction s;
    s.action = actions[i];
    s.start = step.time.value_or(0.0);
    s.duration = step.duration.value_or(0.0);
    s.name = step_name(step);
    bound.steps.push_back(std::move(s));
  }
  std::stable_sort(bound.steps.begin(), bound.steps.end(),
                   [](const ScheduledAction& a, const ScheduledAction& b) { return a.start < b.start; });
  bound.task = std::move(task);
  return bound;
}

Plan steps_of(const ExecutingPlan& plan) {
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
  return steps;
}

ExecutingPlan with_all_conditions(const ExecutingPlan& plan) {
  const Plan steps = steps_of(plan);
  // Validation from the task's initial state says nothing about a plan made
  // from a later state; it is run only to ground the plan's steps in full.
  PlanValidator validator(plan.task->lifted, ValidatorOptions{plan.epsilon, false});
  validator.validate(steps);
  return bind_plan(validator.world_snapshot(), steps, plan.epsilon);
}

std::vector<std::string> step_names_from(const ExecutingPlan& plan, double from) {
  std::vector<std::string> names;
  for (const ScheduledAction& s : plan.steps) {
    if (s.start + 1e-9 >= from) names.push_back(s.name);
  }
  return names;
}

std::size_t plan_distance(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  // The measure diverse planning keeps plans apart by: one definition.
  return action_multiset_distance(a, b);
}

std::size_t plan_distance(const ExecutingPlan& before, const ExecutingPlan& after, double from) {
  return plan_distance(step_names_from(before, from), step_names_from(after, from));
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
