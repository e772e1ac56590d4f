#include "planner/diverse_plans.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <deque>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <unordered_map>

namespace alplan {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::vector<std::string> step_names(const Plan& plan) {
  std::vector<std::string> names;
  names.reserve(plan.steps.size());
  for (const PlanStep& s : plan.steps) names.push_back(plan_step_name(s));
  return names;
}

// The task without the given ground actions: a view sharing everything
// else, so that a search cannot use them.
std::shared_ptr<const GroundTask> without_actions(const std::shared_ptr<const GroundTask>& task,
                                                  const std::set<ActionId>& removed) {
  if (removed.empty()) return task;
  auto view = std::make_shared<GroundTask>(*task);
  std::vector<GroundAction> kept;
  kept.reserve(task->actions.size() - removed.size());
  for (ActionId a = 0; a < task->actions.size(); ++a) {
    if (!removed.count(a)) kept.push_back(task->actions[a]);
  }
  view->actions.mutate() = std::move(kept);
  return view;
}

// Checks found plans against the task itself, from its initial state, as
// printed: a view only ever removes actions, so a plan valid there should
// be valid here; this makes it so rather than assuming it.
class FullTaskCheck {
 public:
  FullTaskCheck(std::shared_ptr<const GroundTask> task, double epsilon)
      : task_(std::move(task)), start_(initial_start(*task_)), epsilon_(epsilon) {
    for (ActionId a = 0; a < task_->actions.size(); ++a) ids_.emplace(task_->action_name(task_->actions[a]), a);
  }

  // The task's ids of the plan's steps; empty when a step is not one of its actions.
  std::vector<ActionId> actions(const Plan& plan) const {
    std::vector<ActionId> out;
    for (const PlanStep& s : plan.steps) {
      const auto id = ids_.find(plan_step_name(s));
      if (id == ids_.end()) return {};
      out.push_back(id->second);
    }
    return out;
  }

  bool valid(const FoundPlan& found) const {
    const Plan printed = read_plan(found.text, "diverse plan").plan;
    const std::vector<ActionId> ids = actions(printed);
    if (ids.size() != printed.steps.size()) return false;
    return validate_printed_from(*task_, start_, printed, ids, {}, epsilon_).valid;
  }

 private:
  std::shared_ptr<const GroundTask> task_;
  PlanningStart start_;
  double epsilon_;
  std::unordered_map<std::string, ActionId> ids_;
};

struct Branch {
  std::set<ActionId> removed;
};

class DiverseSearch {
 public:
  DiverseSearch(std::shared_ptr<const GroundTask> task, const DiversePlanOptions& options)
      : task_(std::move(task)), options_(options), check_(task_, options.planner.epsilon), random_(options.seed) {}

  DiversePlans run() {
    const Clock::time_point began = Clock::now();
    const std::size_t max_calls = options_.max_planner_calls ? options_.max_planner_calls : 8 * options_.k;
    std::deque<Branch> queue{Branch{}};
    seen_.insert({});
    while (!queue.empty() && out_.plans.size() < options_.k && out_.planner_calls < max_calls) {
      const double left = options_.time_limit - since(began);
      if (left <= 0.0) break;
      const Branch branch = std::move(queue.front());
      queue.pop_front();
      if (const std::optional<FoundPlan> found = search(branch, left)) {
        keep_if_distant(*found);
        for (Branch& child : children(branch, found->plan)) queue.push_back(std::move(child));
      }
    }
    out_.exhausted = queue.empty();
    out_.seconds = since(began);
    return std::move(out_);
  }

 private:
  std::optional<FoundPlan> search(const Branch& branch, double seconds_left) {
    PlannerOptions planner = options_.planner;
    planner.time_limit = std::min(planner.time_limit, seconds_left);
    const PlannerResult result = Planner(without_actions(task_, branch.removed), planner).plan();
    if (out_.planner_calls++ == 0) {
      out_.first_status = result.status;
      out_.message = result.message;
    }
    if (!result.best() || !result.best()->validation.valid) return std::nullopt;
    return *result.best();
  }

  void keep_if_distant(const FoundPlan& found) {
    for (const FoundPlan& kept : out_.plans) {
      if (plan_action_distance(kept.plan, found.plan) < options_.min_distance) return;
    }
    // Never return a plan the task itself rejects, whatever the view said.
    if (check_.valid(found)) out_.plans.push_back(found);
  }

  // One branch per distinct action of the plan, each removing it too.
  std::vector<Branch> children(const Branch& parent, const Plan& plan) {
    std::vector<ActionId> order;
    for (ActionId a : check_.actions(plan)) {
      if (std::find(order.begin(), order.end(), a) == order.end()) order.push_back(a);
    }
    if (options_.seed != 0) std::shuffle(order.begin(), order.end(), random_);
    std::vector<Branch> out;
    for (ActionId a : order) {
      Branch child = parent;
      child.removed.insert(a);
      if (seen_.insert(child.removed).second) out.push_back(std::move(child));
    }
    return out;
  }

  std::shared_ptr<const GroundTask> task_;
  const DiversePlanOptions& options_;
  FullTaskCheck check_;
  std::mt19937_64 random_;
  std::set<std::set<ActionId>> seen_;  // removal sets already queued
  DiversePlans out_;
};

}  // namespace

std::string plan_step_name(const PlanStep& step) {
  std::string name = "(" + step.action;
  for (const std::string& arg : step.args) name += " " + arg;
  return name + ")";
}

std::size_t action_multiset_distance(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  std::map<std::string, long> count;
  for (const std::string& s : a) ++count[s];
  for (const std::string& s : b) --count[s];
  std::size_t distance = 0;
  for (const auto& [name, c] : count) distance += static_cast<std::size_t>(std::abs(c));
  return distance;
}

std::size_t plan_action_distance(const Plan& a, const Plan& b) {
  return action_multiset_distance(step_names(a), step_names(b));
}

DiversePlans find_diverse_plans(const std::shared_ptr<const GroundTask>& task, const DiversePlanOptions& options) {
  return DiverseSearch(task, options).run();
}

}  // namespace alplan
