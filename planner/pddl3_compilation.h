// PDDL 3 (Gerevini & Long 2005) compiled into the task the search plans
// with: a pass on the ground task, plain data in and out, in the manner of
// Edelkamp's compilation of plan constraints into PDDL 2.2 (ICAPS 2006) and
// Keyder & Geffner's of soft goals into hard ones (JAIR 2009), not OPTIC's
// automata in the search state. Why: the temporal relaxed planning graph
// then sees every compiled requirement as a goal it can plan for, and the
// simple temporal network orders `within` deadlines against the plan as it
// orders timed initial literals, with no new machinery in the search.
//
// What each construct becomes, the hard ones and the preferences the caller
// enforces (PreferenceSelection); every other preference is dropped and
// costs what the validator counts against the plan:
// - (at end φ) and a goal preference: φ joins the goal.
// - (sometime φ): a goal fact `pddl3-done-K` that only a witness action
//   adds, an instantaneous action whose precondition is φ (one witness per
//   disjunct of a disjunction, so that the relaxation sees each).
// - (within t φ): the same, the witness also needing `pddl3-open-K`, which
//   a timed literal deletes at t + 2 epsilon: a witness by t + epsilon,
//   reading φ as the happenings up to t left it (without continuous change;
//   with it, the literal is at t and φ must be made by t - 2 epsilon).
// - (always φ): kept as a hard constraint of the compiled task, which the
//   successor generator checks in every state it makes (successor_generator.h).
// - a precondition preference: its condition joins the action's condition.
// - a hard (always-within t φ ψ), φ a single fact f false at first, ψ a
//   conjunction of literals, no timed literal adding f or breaking ψ: a
//   durative watch `pddl3-watch-K` of at most t adds `pddl3-watching-K` at
//   its start and needs ψ at its end; a snap that adds f needs a watch
//   running, and a snap that breaks ψ needs a watch running or f false
//   (conditional effects counted as if their condition held). Then every state with f
//   and not ψ has, since f was last added, a watch that ends within t of
//   that addition with ψ in the state before its end, at or after that
//   state: the deadline VAL opens there is met. A plan whose ψ comes in the
//   last epsilon of the t, or that needs two watches of one constraint at
//   once, is lost, so the compiled task's exhaustion proves nothing
//   (GroundTrajectory::approximations, read by proof_limits).
// - at-most-once, sometime-before, sometime-after, hold-during and
//   hold-after: monitor facts the task's snaps keep, with the forms they
//   take and why each is exact or stricter (pddl3_order_constraints.h);
//   not from an observed state, whose history they would need.
// Always-within in other forms, and the forms pddl3_order_constraints.h
// cannot take, are refused when hard, named with their position, and never
// enforced when soft.
//
// Exactness: a plan of the compiled task without its witness steps is a plan
// of the original task that meets every hard and every enforced constraint
// (the witness reads the state VAL observes after the last happening that
// writes what φ reads, no later than the deadline), and each such plan of
// the original becomes one of the compiled task by adding a witness where φ
// holds, epsilon after its last writer (with continuous change, only where φ
// is made 2 epsilon before the deadline). The
// `always` check is stricter than VAL where two snaps share a time (VAL sees
// one happening, the search the state between them), so a search exhausted
// under it proves nothing (search_pipeline.h, proof_limits).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/ground_task.h"

namespace alplan {

// Which preferences (indices into TrajectoryConstraints::preferences) the
// compiled task holds as hard: each of their instances, wherever it occurs.
struct PreferenceSelection {
  std::vector<bool> enforced;
  bool contains(std::uint32_t preference) const { return preference < enforced.size() && enforced[preference]; }
};

struct CompiledTrajectory {
  // Its lifted task names the added actions (witnesses, watches) after the
  // original schemas: steps of those are not steps of the original task.
  std::shared_ptr<const GroundTask> task;
  // Set when a hard constraint cannot be compiled: "what (where)".
  std::optional<std::string> refused;
  // Set when the states seen before the start violated a hard constraint:
  // no plan from here can mend it (a proof, not a refusal).
  std::optional<std::string> broken;
};

class TrajectoryMonitor;

// Planning from a state observed at `now` (PlanningStart): the monitor of
// the states seen before it, over the task being compiled. A `sometime` or
// `within` it saw met needs no witness; a constraint it saw violated, or a
// `within` whose deadline is past, is not enforced (broken, when hard); a
// hard `always-within` with a deadline still open is refused, since a
// watch cannot start in the past.
struct TrajectorySoFar {
  const TrajectoryMonitor* seen = nullptr;
  double now = 0.0;
  const std::vector<FactId>* facts = nullptr;  // the observed state
};

// Whether the task has PDDL 3 the search cannot take as it is: preferences
// anywhere, or constraints other than hard `always`.
bool needs_compilation(const GroundTask& task);

// Whether every instance of a preference has an operator the compilation
// can enforce (goal and precondition preferences, at end, always, sometime,
// within, and the order operators; one whose form the compilation cannot
// take is left unenforced when a round selects it).
bool enforceable(const GroundTask& task, std::uint32_t preference);

// `epsilon`: the planner's separation of dependent happenings (PlannerOptions),
// which places the `within` witnesses' deadlines.
CompiledTrajectory compile_trajectory(const GroundTask& task, const PreferenceSelection& selection,
                                      const TrajectorySoFar& so_far = {}, double epsilon = 0.001);

}  // namespace alplan
