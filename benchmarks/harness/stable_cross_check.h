// A second opinion on `stable`'s proven distances (issue 43): minimum-
// distance repair compiled into a CLASSICAL task, as Saetti & Scala's S-RESA
// compilation does for classical plans (KER 2025; ICAPS 2022), and solved
// with the planner's A* on LM-cut. A checker must not share code with what
// it checks: nothing here comes from repair/stable_compilation (this file
// writes its own substitution, its own keep/forgo actions and its own
// reading of the old plan); what the two share is the parser's AST, the
// reformulated problem (the question both answer) and the planner that
// searches, which `stable` uses on a temporal task and this on a classical
// one.
//
// The classical task. Every action of the domain costs 1 (total-cost), and
// a durative action is compressed: it runs alone, start then end, so its
// at-start conditions are read in the state before it, its over-all and
// at-end conditions in the state its own start effects leave, and its
// start effects are applied before its end effects. The compression is
// written as two classical actions under a lock, X-start (at-start
// conditions, start effects, cost 1) and X-end (over-all and at-end
// conditions, end effects, cost 0), joined by (xcheck-mid-X params) and a
// global (xcheck-free) that X-start takes and X-end gives back: nothing can
// come between the two, so the pair is the one instantaneous action the
// compression describes, without rewriting conditions through the start
// effects (two parameters naming one object would defeat a syntactic
// rewriting). Durations are dropped; where a duration reads a function, the
// start requires it to be defined and positive, as the grounder requires of
// a durative action. Per occurrence i of the old plan's remaining steps: a
// parameter-free copy keep-i (cost 0) that needs (xcheck-pending-i), deletes
// it and adds (xcheck-done-i) when it ends; and forgo-i (cost 1), from
// pending-i to done-i. The goal is the problem's and every done-i; the
// metric minimises total-cost, so a plan costs its distance from the old
// steps: |new \ old| + |old \ new| over multisets (Fox et al. 2006).
// Actions still running when the world changed end at timed literals in the
// reformulated problem; here their ends are applied to the initial state
// (every committed end happens before the new plan begins).
//
// Why the minimum is `stable`'s. (1) A classical plan runs in the temporal
// task: wait until every committed end has happened, then run its actions
// one at a time, each after the one before has ended. Nothing in the IPC
// 2002 stability domains has a deadline, so waiting costs nothing, and the
// distance, over a multiset, does not see the order: the classical minimum
// is never below the temporal one. (2) Conversely, a temporal plan whose
// actions also run one at a time after the committed ends, in the order of
// their starts or of their ends, is a classical plan with the same multiset:
// the classical minimum is never above its distance. On these domains no
// action needs another one running (no required concurrency: no condition
// is made true only while another action runs), so a minimum-distance plan
// can be sequenced; the check does not take that on trust. It runs the
// temporal plan `stable` returned one action at a time from the state after
// the committed ends (sequential_gap): when that fails, `stable`'s plan used
// concurrency, or a committed end's state before it happened (the
// reformulation drops a running action's over-all conditions, so a new
// action may use, say, a hoist's crate while the drop that will put it down
// still runs), and the two tasks may have different minima.
//
// Not comparable, never agreement: where `stable`'s plan cannot be
// sequenced (required concurrency, committed ends used early); where the
// problem has timed literals of its own (a window or a deadline makes
// waiting cost something); where a duration is read by an effect or a
// condition, numeric values change (no effect on a function is compiled:
// total-cost is the distance alone), change is continuous, or the task has
// derived predicates, conditional effects in durative actions or PDDL 3.
// There the cross-check says "not comparable" and why, and computes nothing.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "repair/executing_plan.h"
#include "repair/repair_strategy.h"

namespace alplan::bench {

// One occurrence of the old plan's remaining steps: a ground action.
struct CrossCheckStep {
  std::string schema;
  std::vector<std::string> args;
};

// The old plan's steps that start at or after `now` (those before are
// committed), read off the plan independently of `stable`.
std::vector<CrossCheckStep> steps_from(const repair::ExecutingPlan& plan, double now);

struct ClassicalRepairTask {
  pddl::Domain domain;
  pddl::Problem problem;
  // Why the classical minimum need not be the temporal one ("" when it is,
  // up to the sequencing that cross_check_stable checks on stable's plan).
  std::string not_comparable;
};

// The classical task for the reformulated problem (its timed literals the
// running actions' committed ends) and the old steps. `own_timed_literals`:
// the problem had timed literals before reformulation. Throws
// std::invalid_argument when a step names no schema of the domain, has the
// wrong number of objects, or the domain already uses a name xcheck-...
ClassicalRepairTask compile_classical_repair(const pddl::Domain& domain, const pddl::Problem& reformulated,
                                             const std::vector<CrossCheckStep>& old,
                                             bool own_timed_literals = false);

enum class CrossCheckStatus { Proven, NotProven, NotComparable };
const char* to_string(CrossCheckStatus status);

struct CrossCheckResult {
  CrossCheckStatus status = CrossCheckStatus::NotComparable;
  std::optional<std::size_t> distance;  // the classical plan's, proven minimal when Proven
  std::string note;                      // why not comparable or not proven; the plan's counts when proven
  // A limit of the planner's proofs that Proven does not hold against (one
  // about what a happening may hold; every happening here has one action).
  std::string waived;
  double seconds = 0.0;
};

// Grounds and solves the classical task with complete(wastar(lmcut, w=1,
// order=metric, preferred=false)) within `seconds`: Proven when the planner
// says that configuration proves cost-optimality and it returned a plan.
CrossCheckResult solve_classical_repair(const ClassicalRepairTask& task, double seconds);

// Why `plan` (its steps from `now`) cannot run one action at a time, each
// compressed, in the order of their starts nor in the order of their ends,
// from its task's initial state after every timed literal: "" when it can.
std::string sequential_gap(const repair::ExecutingPlan& plan, double now);

// The cross-check of one perturbation: the problem reformulated from
// `request` as `stable` reformulates it, the old plan's steps from
// request.now, solved classically; `stable_plan` (its plan, or null) is
// the witness that the two tasks' minima agree (sequential_gap).
CrossCheckResult cross_check_stable(const repair::RepairRequest& request, const repair::ExecutingPlan* stable_plan,
                                    double seconds);

}  // namespace alplan::bench
