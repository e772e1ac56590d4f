// patch: keep what is left of the plan and swap the object whose condition
// failed for an equivalent one — of the same type, else of the same parent
// type (the ontology's, so a mug can stand in for a glass) — that the
// problem knows or perception has just recognised. No search when the
// patched plan is valid from the observed state; otherwise replan.
#include <algorithm>
#include <chrono>
#include <set>

#include "repair/reformulation.h"
#include "repair/repair_strategy.h"

namespace alplan::repair {
namespace {

std::optional<std::string> parent_type(const pddl::Domain& domain, const TypeOntology* ontology,
                                       const std::string& type) {
  for (const pddl::TypeDeclaration& t : domain.types) {
    if (t.name == type && !t.parents.empty()) return t.parents.front();
  }
  if (ontology) return ontology->parent(type);
  return std::nullopt;
}

class PatchStrategy : public RepairStrategy {
 public:
  explicit PatchStrategy(StrategyOptions options) : options_(std::move(options)) {}
  std::string name() const override { return "patch"; }

  RepairResult repair(const RepairRequest& request) override {
    const auto began = std::chrono::steady_clock::now();
    pddl::Problem problem = *request.problem;
    RepairRequest seen = request;
    const std::vector<RecognizedObject> recognized = integrate_recognized(seen, problem);
    const pddl::Problem reformulated =
        reformulate(*request.domain, problem, seen.observed, request.in_progress, request.now);
    std::shared_ptr<const GroundTask> task;
    bool reused = false;
    try {
      task = ground_problem(*request.domain, reformulated, request.grounding, &reused);
    } catch (const std::exception&) {
      task = nullptr;
    }
    if (task) {
      for (const std::string& failed : failed_objects(request)) {
        for (const std::string& candidate : candidates(request, problem, failed)) {
          std::optional<ExecutingPlan> patched = rename(request, task, failed, candidate);
          if (!patched) continue;
          RepairResult result;
          result.repaired = true;
          result.plan = std::move(patched);
          result.problem = problem;
          result.integrated = recognized;
          result.how = "patched the plan: " + candidate + " (" + *object_type(problem, candidate) +
                       ") takes the place of " + failed + " (" + *object_type(problem, failed) +
                       ") in the remaining steps; no search was needed";
          result.reused_grounding = reused;
          result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
          return result;
        }
      }
    }
    RepairResult result = replan_from(seen, *request.domain, problem, options_.planner);
    result.integrated = recognized;
    if (result.repaired) {
      result.how = "no equivalent object made the old plan work, so it replanned: " +
                   describe_remedy(*result.plan, request.now);
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    return result;
  }

 private:
  // Objects named by the violated condition that the remaining plan uses.
  static std::vector<std::string> failed_objects(const RepairRequest& request) {
    std::set<std::string> in_plan;
    for (const ScheduledAction& s : request.plan->steps) {
      if (s.start + 1e-9 < request.now) continue;
      for (const std::string& w : words_of(s.name)) in_plan.insert(w);
    }
    std::vector<std::string> out;
    const std::vector<std::string> named = words_of(request.failure->condition);
    for (std::size_t i = 1; i < named.size(); ++i) {
      if (in_plan.count(named[i]) && object_type(*request.problem, named[i])) out.push_back(named[i]);
    }
    return out;
  }

  static std::vector<std::string> candidates(const RepairRequest& request, const pddl::Problem& problem,
                                             const std::string& failed) {
    const std::string type = *object_type(problem, failed);
    const std::optional<std::string> parent = parent_type(*request.domain, request.ontology, type);
    std::vector<std::string> same, related;
    for (const pddl::TypedName& o : problem.objects) {
      if (o.name == failed || o.types.empty()) continue;
      if (o.types.front() == type) {
        same.push_back(o.name);
      } else if (parent && parent_type(*request.domain, request.ontology, o.types.front()) == parent) {
        related.push_back(o.name);
      }
    }
    same.insert(same.end(), related.begin(), related.end());
    return same;
  }

  std::optional<ExecutingPlan> rename(const RepairRequest& request, const std::shared_ptr<const GroundTask>& task,
                                      const std::string& from, const std::string& to) const {
    Plan plan;
    for (const ScheduledAction& s : request.plan->steps) {
      if (s.start + 1e-9 < request.now) continue;
      std::vector<std::string> w = words_of(s.name);
      PlanStep step;
      step.time = s.start;
      step.action = w.front();
      for (std::size_t i = 1; i < w.size(); ++i) step.args.push_back(w[i] == from ? to : w[i]);
      step.duration = s.duration;
      plan.steps.push_back(step);
    }
    try {
      ExecutingPlan bound = bind_plan(task, plan, options_.planner.epsilon);
      if (validate_from_now(bound, request.now).valid) return bound;
    } catch (const std::invalid_argument&) {
      // The renamed step is not an action of the task: the object cannot do it.
    }
    return std::nullopt;
  }

  StrategyOptions options_;
};

}  // namespace

std::unique_ptr<RepairStrategy> make_patch_strategy(const StrategyOptions& options) {
  return std::make_unique<PatchStrategy>(options);
}

}  // namespace alplan::repair
