// Diverse plans: up to k plans for one task, each pair at least d apart
// under the action-set distance, so that a robot has alternatives ready
// when one plan's object or route fails.
//
// Distance. Plans are compared as multisets of ground actions, |A\B| +
// |B\A| (the action-set distance of Fox, Gerevini, Long & Serina, "Plan
// stability: replanning versus plan repair", ICAPS 2006, and of Nguyen, Do,
// Gerevini, Serina, Srivastava & Kambhampati, "Generating diverse plans to
// handle unknown and partially known user preferences", AIJ 190, 2012,
// whose multiset form this is). Times and durations are ignored: two
// temporal plans with the same actions at other times are at distance 0.
// The repair study's stability (repair/monitor.h, plan_distance) is this
// measure on the steps still to come.
//
// Method. Katz & Sohrabi ("Reshaping diverse planning", AAAI 2020) forbid
// each found plan by reformulating the task and plan again; we do not
// compile the task. We follow the iterate-and-forbid idea with a cheaper
// forbidding that works for temporal and numeric tasks alike: each found
// plan P spawns searches on views of the task without one of P's ground
// actions (as many as P has distinct actions, breadth first, the removed
// actions accumulating along a branch), and a plan is kept only when it is
// at least d from every plan kept before (a distance filter, as Nguyen et
// al.'s d-distant sets ask). Removing an action forbids every plan using
// it, not just P, so this is incomplete: a plan that contains all of P's
// actions plus d others is never found, and "fewer than k" means "fewer
// under this method and budget", never a proof that no more exist.
//
// Contract: every returned plan is valid for `task` itself (not only for
// the view it was found on), checked by the validator from the task's
// initial state before it is returned. Deterministic given the options
// when the budgets are expansions (node_limit); a time limit can stop a
// search earlier on a loaded machine. No mutable global state.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "planner/planner.h"

namespace alplan {

struct DiversePlanOptions {
  std::size_t k = 3;
  std::size_t min_distance = 2;  // d: every pair of plans at least this far apart
  // Each search's options; its time_limit and node_limit are one plan's budget.
  PlannerOptions planner;
  // The budget of the whole: searches (0: 8 per plan asked for) and seconds.
  std::size_t max_planner_calls = 0;
  double time_limit = std::numeric_limits<double>::infinity();
  // 0: a plan's actions are removed in plan order; otherwise in an order
  // shuffled with this seed (other branches, other plans).
  std::uint64_t seed = 0;
};

struct DiversePlans {
  std::vector<FoundPlan> plans;  // the first is the planner's plan for the whole task
  // The first search's status and message: why there is no plan at all.
  PlannerResult::Status first_status = PlannerResult::Status::LimitReached;
  std::string message;
  std::size_t planner_calls = 0;
  // Every branch was searched to its end: no more plans under this method
  // (fewer than k found means the method found no more, not that none exist).
  bool exhausted = false;
  double seconds = 0.0;
};

// "(name arg ...)", as the task and the monitor name ground actions.
std::string plan_step_name(const PlanStep& step);
// |A\B| + |B\A| over multisets of ground action names.
std::size_t action_multiset_distance(const std::vector<std::string>& a, const std::vector<std::string>& b);
// The distance of two plans' steps, times ignored.
std::size_t plan_action_distance(const Plan& a, const Plan& b);

// Up to options.k plans for the task from its initial state, pairwise at
// least options.min_distance apart.
DiversePlans find_diverse_plans(const std::shared_ptr<const GroundTask>& task, const DiversePlanOptions& options);

}  // namespace alplan
