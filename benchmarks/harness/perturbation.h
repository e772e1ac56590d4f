// Perturbations of a plan's execution for the plan-stability testbed
// (`alplan bench stability`, stability_bench.h), after Fox, Gerevini, Long
// and Serina, "Plan stability: replanning versus plan repair" (ICAPS 2006):
// the world diverges from what the plan expects, or the goals change, while
// the plan runs. Three kinds, each drawn against the state the execution has
// reached and the steps still to run, so that it touches the plan:
// - fact: a fact a remaining step needs and the state holds becomes false;
//   where the task knows a fact of the same predicate and arguments but the
//   last (a place, mostly), that one becomes true instead: the truck is at
//   another stop, not nowhere;
// - object: an object a remaining step uses (and no goal names) is lost:
//   every fact the state holds about it becomes false;
// - goal: a goal is added, a reachable fact of a goal's predicate about an
//   object the goals do not yet place.
// Nothing here decides whether the plan still works afterwards: the
// testbed validates the remaining plan from the perturbed state and draws
// again when it does.
#pragma once

#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/ground_task.h"
#include "repair/executing_plan.h"
#include "repair/world_state.h"

namespace alplan::bench {

enum class PerturbationKind : unsigned char { Fact, Object, Goal };

const char* to_string(PerturbationKind kind);
std::optional<PerturbationKind> perturbation_kind(const std::string& name);

struct Perturbation {
  PerturbationKind kind = PerturbationKind::Fact;
  std::string description;
  std::vector<std::pair<repair::AtomKey, bool>> changes;  // to the state
  std::vector<repair::AtomKey> added_goals;
};

struct PerturbationContext {
  const repair::WorldState* state = nullptr;  // what the execution reached
  // The plan, bound to a task that keeps every condition of its steps
  // (repair::with_all_conditions): static facts can be perturbed too.
  const repair::ExecutingPlan* plan = nullptr;
  double now = 0.0;  // steps from here on are still to run
  // Every fact the grounding found reachable from the initial state: where
  // a fact may move to, and which goals can be added.
  const GroundTask* reachable = nullptr;
  std::vector<repair::AtomKey> goals;  // the problem's goal atoms
  // Objects of actions running now: losing one would break a commitment
  // the reformulation keeps, not the plan.
  std::vector<std::string> busy;
};

// One perturbation of `kind`, or nothing when the context offers none (no
// object the goals leave free, no goal to add).
std::optional<Perturbation> draw_perturbation(PerturbationKind kind, const PerturbationContext& context,
                                              std::mt19937_64& random);

// The problem's goal as atoms: a conjunction of positive literals, as in
// every domain of the testbed; throws std::invalid_argument otherwise.
std::vector<repair::AtomKey> goal_atoms(const pddl::Problem& problem);
// The problem with `added` goals conjoined to its goal.
pddl::Problem with_goals(const pddl::Problem& problem, const std::vector<repair::AtomKey>& added);

}  // namespace alplan::bench
