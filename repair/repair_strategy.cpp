#include "repair/repair_strategy.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "planner/happening_executor.h"
#include "repair/reformulation.h"

namespace alplan::repair {

std::unique_ptr<RepairStrategy> make_patch_strategy(const StrategyOptions& options);
std::unique_ptr<RepairStrategy> make_adapt_strategy(const StrategyOptions& options);
std::unique_ptr<RepairStrategy> make_stable_strategy(const StrategyOptions& options);
std::unique_ptr<RepairStrategy> make_switch_strategy(const StrategyOptions& options);

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

std::string seconds_text(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", t);
  return buffer;
}

// The objects a plan's steps from `from` on name, in order of first use.
std::vector<std::string> objects_used(const ExecutingPlan& plan, double from) {
  std::vector<std::string> used;
  for (const ScheduledAction& s : plan.steps) {
    if (s.start + 1e-9 < from) continue;
    for (ObjectId o : plan.task->actions[s.action].args) {
      const std::string& name = plan.task->lifted->objects[o];
      if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
    }
  }
  return used;
}

class ReplanStrategy : public RepairStrategy {
 public:
  explicit ReplanStrategy(StrategyOptions options) : options_(std::move(options)) {}
  std::string name() const override { return "replan"; }
  RepairResult repair(const RepairRequest& request) override {
    RepairResult result = replan_from(request, *request.domain, *request.problem, options_.planner);
    if (result.repaired) result.how = "replanned from the observed state: " + describe_remedy(*result.plan, request.now);
    return result;
  }

 private:
  StrategyOptions options_;
};

class SubstituteStrategy : public RepairStrategy {
 public:
  explicit SubstituteStrategy(StrategyOptions options) : options_(std::move(options)) {}
  std::string name() const override { return "substitute"; }
  RepairResult repair(const RepairRequest& request) override {
    pddl::Problem problem = *request.problem;
    RepairRequest seen = request;
    // Substitution's latency includes asking perception: it is what the
    // strategy depends on, and replan does without it.
    const auto began = std::chrono::steady_clock::now();
    const std::vector<RecognizedObject> integrated = integrate_recognized(seen, problem);
    const double perception = since(began);
    RepairResult result = replan_from(seen, *request.domain, problem, options_.planner);
    result.perception_seconds = perception;
    result.seconds += perception;
    result.integrated = integrated;
    if (!result.repaired) return result;
    std::string how;
    for (const RecognizedObject& o : integrated) {
      const std::vector<std::string> used = objects_used(*result.plan, request.now);
      const bool in_plan = std::find(used.begin(), used.end(), o.name) != used.end();
      std::string kind = o.type;
      if (request.ontology) {
        const std::vector<std::string> lineage = request.ontology->lineage(o.type);
        if (lineage.size() > 1) kind += ", a kind of " + lineage[1];
      }
      const std::string when = o.seen_at >= 0.0 && o.seen_at + 1e-9 < request.now
                                   ? " (seen at " + seconds_text(o.seen_at) + ")"
                                   : "";
      how += "perception recognised " + o.name + " (" + kind + ") in " + o.location + when +
             (in_plan ? " and the new plan uses it; " : ", which the new plan does not need; ");
    }
    if (integrated.empty()) how = "perception recognised no new object; ";
    result.how = how + describe_remedy(*result.plan, request.now);
    return result;
  }

 private:
  StrategyOptions options_;
};

class SuggestStrategy : public RepairStrategy {
 public:
  explicit SuggestStrategy(StrategyOptions options) : options_(std::move(options)) {}
  std::string name() const override { return "suggest"; }
  RepairResult repair(const RepairRequest& request) override {
    RepairResult result =
        replan_from(request, *request.domain, *request.problem, options_.planner, options_.handling_actions);
    if (result.repaired) {
      result.how = "no object is handed over; instead " + describe_remedy(*result.plan, request.now);
    } else {
      // Name the planner's reason: typically a goal no suggestion reaches
      // (a suggestion entertains; it neither soothes nor cheers).
      result.how = "no activity can be suggested to reach the goal: " + result.how;
    }
    return result;
  }

 private:
  StrategyOptions options_;
};

}  // namespace

RepairResult replan_from(const RepairRequest& request, const pddl::Domain& domain, const pddl::Problem& problem,
                         const PlannerOptions& options, const std::set<std::string>& excluded) {
  const auto began = std::chrono::steady_clock::now();
  RepairResult result;
  result.problem = reformulate(domain, problem, request.observed, request.in_progress, request.now);
  PlanningOutcome outcome =
      plan_in_process(domain, result.problem, request.now, options, request.grounding, excluded, request.history);
  result.planner_calls = 1;
  result.reused_grounding = outcome.reused_grounding;
  result.repaired = outcome.plan.has_value();
  result.plan = std::move(outcome.plan);
  if (!result.repaired) result.how = no_plan_reason(outcome.status, outcome.message);
  // The problem to carry on with keeps the base's initial state: the world,
  // not the problem, says what holds from now on.
  result.problem.init = problem.init;
  result.problem.numeric_init = problem.numeric_init;
  result.problem.timed_literals = problem.timed_literals;
  result.seconds = since(began);
  return result;
}

ValidationResult validate_from_now(const ExecutingPlan& plan, double now) {
  const GroundTask& task = *plan.task;
  std::vector<ScheduledStep> steps;
  for (std::size_t i = 0; i < plan.steps.size(); ++i) {
    const ScheduledAction& a = plan.steps[i];
    steps.push_back({a.action, i, 0, a.start, a.duration, a.name, false});
  }
  ExecutionStart start;
  start.state = ExplicitState::of(task.initial_facts, task.initial_values);
  start.now = now;
  HappeningExecutor executor(task, ValidatorOptions{plan.epsilon, false});
  return executor.run(steps, steps.size(), start);
}

std::optional<ExecutingPlan> bind_validated(const std::shared_ptr<const GroundTask>& task, Plan plan, double now,
                                            double epsilon, std::string& why) {
  std::stable_sort(plan.steps.begin(), plan.steps.end(), [](const PlanStep& a, const PlanStep& b) {
    return a.time.value_or(0.0) < b.time.value_or(0.0);
  });
  ExecutingPlan bound;
  try {
    bound = bind_plan(task, plan, epsilon);
  } catch (const std::exception& error) {
    why = error.what();
    return std::nullopt;
  }
  const ValidationResult check = validate_from_now(bound, now);
  if (check.valid) return bound;
  why = check.violation ? check.violation->message() : "the validator rejects it";
  return std::nullopt;
}

std::vector<RecognizedObject> integrate_recognized(RepairRequest& request, pddl::Problem& problem) {
  std::vector<RecognizedObject> integrated;
  if (!request.recognizer) return integrated;
  std::set<std::string> types{"object"};
  for (const pddl::TypeDeclaration& t : request.domain->types) types.insert(t.name);
  // What the camera sees now first (nearest), then what it saw on the way.
  std::vector<RecognizedObject> candidates = request.recognizer->recognize(request.observed, request.robot_location);
  for (const RecognizedObject& o : request.recognizer->recognize_sightings(request.sightings)) {
    const bool again = std::any_of(candidates.begin(), candidates.end(),
                                   [&](const RecognizedObject& c) { return c.name == o.name; });
    if (!again) candidates.push_back(o);
  }
  for (const RecognizedObject& o : candidates) {
    if (object_type(problem, o.name) || !types.count(o.type)) continue;
    pddl::TypedName object;
    object.name = o.name;
    object.types = {o.type};
    problem.objects.push_back(object);
    request.observed.set({"be", o.name, o.location}, true);
    request.observed.set({"available", o.name}, true);
    integrated.push_back(o);
  }
  return integrated;
}

std::string describe_remedy(const ExecutingPlan& plan, double from) {
  std::string last;
  std::size_t steps = 0;
  for (const ScheduledAction& s : plan.steps) {
    if (s.start + 1e-9 < from) continue;
    ++steps;
    last = s.name;
  }
  if (steps == 0) return "nothing is left to do";
  std::string objects;
  for (const std::string& o : objects_used(plan, from)) objects += (objects.empty() ? "" : ", ") + o;
  double end = 0.0;
  for (const ScheduledAction& s : plan.steps) end = std::max(end, s.end());
  return "the new plan has " + std::to_string(steps) + " steps, ends with " + last + " at " + seconds_text(end) +
         " and involves " + objects;
}

std::vector<std::string> strategy_names() {
  return {"replan", "substitute", "suggest", "patch", "adapt", "stable", "switch"};
}

std::string strategy_list() {
  std::string list;
  for (const std::string& n : strategy_names()) list += (list.empty() ? "" : ", ") + n;
  return list;
}

std::unique_ptr<RepairStrategy> make_strategy(const std::string& name, const StrategyOptions& options) {
  if (name == "replan") return std::make_unique<ReplanStrategy>(options);
  if (name == "substitute") return std::make_unique<SubstituteStrategy>(options);
  if (name == "suggest") return std::make_unique<SuggestStrategy>(options);
  if (name == "patch") return make_patch_strategy(options);
  if (name == "adapt") return make_adapt_strategy(options);
  if (name == "stable") return make_stable_strategy(options);
  if (name == "switch") return make_switch_strategy(options);
  throw std::invalid_argument("unknown repair strategy '" + name + "' (known: " + strategy_list() + ")");
}

}  // namespace alplan::repair
