#include "planner/validator.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "pddl_parser/writer.h"
#include "planner/formula_evaluation.h"
#include "planner/explicit_state.h"
#include "planner/ground_printer.h"
#include "planner/ground_trajectory.h"
#include "planner/grounder.h"
#include "planner/happening_executor.h"
#include "planner/reachability.h"

namespace alplan {
namespace {

// The validator's world: every part of the task it can ground before seeing
// a plan (initial state, timed literals, goal, metric, axioms), in open
// tables that later steps extend.
void ground_world(const NormalizedTask& lifted, const StaticFacts& statics, GroundTask& world) {
  Instantiator instantiate(lifted, statics, world.facts, world.numeric, {false, true, true});
  for (const GroundAtom& a : lifted.initial_facts) world.initial_facts.push_back(world.facts.intern({a.predicate, a.args}));
  for (const NormalizedTimedLiteral& til : lifted.timed_literals) {
    world.timed_literals.push_back({til.time, world.facts.intern({til.atom.predicate, til.atom.args}), til.positive});
  }
  std::vector<ObjectId> binding(lifted.goal_variable_slots, kNoId);
  world.goal = instantiate.condition(lifted.goal, binding);
  if (lifted.metric) {
    world.metric = GroundMetric{lifted.metric->minimize, instantiate.expression(lifted.metric->expression, {})};
  }
  world.pddl3 = ground_trajectory(lifted, instantiate);
  if (!lifted.derived_rules.empty()) {
    const std::vector<std::uint32_t> strata = derived_strata(lifted);
    // Only at-start atoms are required, so that any state a plan reaches
    // before its first violation is covered.
    const ReachableSet reachable = compute_reachable(lifted, {false, 32, std::nullopt});
    for (const Instantiation& i : reachable.axioms) {
      const DerivedRule& rule = lifted.derived_rules[i.schema];
      std::vector<ObjectId> slots(std::max<std::size_t>(rule.variable_slots, i.args.size()), kNoId);
      std::copy(i.args.begin(), i.args.end(), slots.begin());
      ConditionSet body = instantiate.condition(rule.body, slots);
      if (body.never) continue;
      world.axioms.push_back({world.facts.intern({rule.head, i.args}), std::move(body), strata[rule.head]});
      world.strata = std::max(world.strata, strata[rule.head] + 1);
    }
    std::stable_sort(world.axioms.begin(), world.axioms.end(),
                     [](const GroundAxiom& a, const GroundAxiom& b) { return a.stratum < b.stratum; });
  }
  for (const NumericInitialValue& v : lifted.initial_values) {
    if (lifted.functions[v.function].fluent) world.numeric.intern({v.function, v.args});
  }
  world.initial_values.assign(world.numeric.size(), std::nan(""));
  for (const NumericInitialValue& v : lifted.initial_values) {
    if (auto id = world.numeric.find({v.function, v.args})) world.initial_values[*id] = v.value;
  }
}

std::string step_name(const PlanStep& step) {
  std::string s = "(" + step.action;
  for (const std::string& a : step.args) s += " " + a;
  return s + ")";
}

}  // namespace

PlanValidator::PlanValidator(std::shared_ptr<const NormalizedTask> task, ValidatorOptions options)
    : world_(std::make_shared<GroundTask>()), statics_(StaticFacts::of(*task)), options_(options) {
  world_->lifted = task;
  for (ObjectId o = 0; o < task->objects.size(); ++o) objects_.emplace(task->objects[o], o);
  for (std::uint32_t a = 0; a < task->actions.size(); ++a) schemas_.emplace(task->actions[a].name, a);
  ground_world(*task, statics_, *world_);
}

std::optional<std::size_t> PlanValidator::instantiate_step(const PlanStep& step, std::size_t index,
                                                           Violation& error) {
  const NormalizedTask& lifted = *world_->lifted;
  error.step = index;
  error.line = step.line;
  error.time = step.time.value_or(0.0);
  error.action = step_name(step);
  auto schema = schemas_.find(step.action);
  if (schema == schemas_.end()) {
    error.kind = Violation::Kind::UnknownAction;
    return std::nullopt;
  }
  const ActionSchema& s = lifted.actions[schema->second];
  if (step.args.size() != s.parameters.size()) {
    error.kind = Violation::Kind::BadStep;
    error.condition = s.name + " takes " + std::to_string(s.parameters.size()) + " arguments, the step gives " +
                      std::to_string(step.args.size());
    return std::nullopt;
  }
  std::vector<ObjectId> args;
  for (std::size_t i = 0; i < step.args.size(); ++i) {
    auto object = objects_.find(step.args[i]);
    if (object == objects_.end()) {
      error.kind = Violation::Kind::UnknownObject;
      error.condition = step.args[i];
      return std::nullopt;
    }
    const std::vector<ObjectId>& allowed = lifted.types[s.parameters[i].type].objects;
    if (!std::binary_search(allowed.begin(), allowed.end(), object->second)) {
      error.kind = Violation::Kind::BadStep;
      error.condition = step.args[i] + " is not of type " + lifted.types[s.parameters[i].type].name;
      return std::nullopt;
    }
    args.push_back(object->second);
  }
  if (!s.unsupported.empty()) {
    error.kind = Violation::Kind::Unsupported;
    error.condition = s.unsupported;
    return std::nullopt;
  }
  if (s.durative && !step.duration) {
    error.kind = Violation::Kind::BadStep;
    error.condition = "the durative action " + s.name + " needs a duration [d]";
    return std::nullopt;
  }
  auto key = std::make_pair(schema->second, args);
  auto cached = step_actions_.find(key);
  if (cached != step_actions_.end()) return cached->second;
  Instantiator instantiate(lifted, statics_, world_->facts, world_->numeric, {false, true, true});
  world_->actions.push_back(instantiate.action(schema->second, args));
  step_actions_.emplace(std::move(key), world_->actions.size() - 1);
  return world_->actions.size() - 1;
}

ValidationResult PlanValidator::validate(const Plan& plan) { return run(plan, HappeningObserver{}, options_); }

ValidationResult PlanValidator::validate(const Plan& plan, const HappeningObserver& observer) {
  return run(plan, observer, options_);
}

ValidationResult PlanValidator::validate_exactly(const Plan& plan) {
  ValidatorOptions exact = options_;
  exact.numeric_slack = 0.0;
  return run(plan, HappeningObserver{}, exact);
}

ValidationResult PlanValidator::run(const Plan& plan, const HappeningObserver& observer,
                                    const ValidatorOptions& options) {
  ValidationResult result;
  if (!world_->lifted->unsupported.empty()) {
    Violation v;
    v.kind = Violation::Kind::Unsupported;
    v.condition = world_->lifted->unsupported.front();
    result.violation = v;
    result.violations.push_back(v);
    return result;
  }
  std::vector<ScheduledStep> steps;
  double untimed_clock = 0.0;
  for (std::size_t i = 0; i < plan.steps.size(); ++i) {
    const PlanStep& step = plan.steps[i];
    Violation error;
    std::optional<std::size_t> action = instantiate_step(step, i, error);
    if (!action) {
      result.violations.push_back(error);
      if (!options.report_all) break;
      continue;
    }
    const double start = step.time ? *step.time : (untimed_clock += 1.0);
    steps.push_back({*action, i, step.line, start, step.duration.value_or(0.0), step_name(step)});
  }
  if (!result.violations.empty()) {
    result.violation = result.violations.front();
    return result;
  }
  HappeningExecutor executor(*world_, options);
  if (observer) executor.set_observer(observer);
  return executor.run(steps, plan.steps.size());
}

}  // namespace alplan
