// Planning with PDDL 3 preferences and trajectory constraints
// (Gerevini & Long 2005): the task compiled (pddl3_compilation.h) with a
// growing selection of preferences held as hard, each compiled task planned
// by the search configuration, each plan stripped of its witnesses and
// validated on the original task, whose validator counts what it violates
// and gives its metric.
//
// Round 0 enforces the hard constraints only, so the first plan comes as
// fast as the task without preferences allows. In anytime mode (the
// configuration's engine is `anytime`) rounds follow, in the manner of the
// goal selection of partial-satisfaction planners (van den Briel et al.,
// "Effective approaches for partial satisfaction (over-subscription)
// planning", AAAI 2004; YochanPS, Benton, Do & Kambhampati 2009): each adds
// one preference the best plan violates, the one whose violations cost the
// metric most first, and keeps it when the plan it gives is better, giving
// it up otherwise (it cost more than it saved, or it could not be planned
// within the round's share of the time). The time left then goes to the
// anytime phases on the best selection. Every plan handed on is better than
// the one before under the task's metric (minimised or maximised).
//
// Each compiled task is searched for what the task's metric makes of its
// plans, violations counted (PlannerOptions::Objective): a plan no better
// under the compiled metric, which reads every violation as 0, is handed on
// when it violates less. Where each violation weighs against the plan (a
// minimised metric linear in the `is-violated` terms with non-negative
// weights) the compiled metric is a lower bound on the task's, and the
// anytime phases prune by the best plan's true value; where the metric is
// made only of preferences (trucks, storage), the compiled one is a
// constant and pruning by it would end every phase after the first plan.
//
// From an observed state (a monitor's repair), the states seen before it
// (PlanningStart::history) are run through the validator's trajectory
// monitor first: what they settle is compiled away (TrajectorySoFar), a hard
// constraint they broke makes the task unsolvable from here, and each plan
// is validated from the observed state with that monitor carried on, so its
// value counts the violations of the whole trajectory. Actions still running
// at the start are not supported with PDDL 3 (a monitor commits them as
// timed literals, repair/reformulation.h).
#pragma once

#include <functional>
#include <memory>

#include "planner/temporal_planner.h"

namespace alplan {

class PreferenceSearch {
 public:
  PreferenceSearch(std::shared_ptr<const GroundTask> task, PlannerOptions options);

  PlannerResult plan(const std::function<void(const FoundPlan&)>& on_plan = {});
  PlannerResult plan_from(const PlanningStart& start, const std::function<void(const FoundPlan&)>& on_plan = {});

 private:
  std::shared_ptr<const GroundTask> task_;
  PlannerOptions options_;
};

}  // namespace alplan
