// Plan stability as cost-optimal planning: the compilation behind the
// `stable` repair strategy (Saetti & Scala, "Optimally stable plan repair",
// Knowledge Engineering Review 2025; "Optimising the stability in plan
// repair via compilation", ICAPS 2022). The distance between two plans is
// Fox, Gerevini, Long and Serina's (ICAPS 2006): over multisets of ground
// actions, D(pi0, pi1) = |pi1 \ pi0| + |pi0 \ pi1|.
//
// Contract: given the old plan's remaining steps O (a multiset: occurrence i
// is one step) and the reformulated problem P, compile_stability returns a
// domain D' and problem P' such that every plan of P' maps (map_back) to a
// plan of P, every plan pi of P is the image of a plan of P' whose
// (total-cost) is D(O, pi), and no plan of P' costs less than the distance of
// its image. So a cost-optimal plan of P' maps to a plan of P at minimum
// distance from O, and its cost is that distance. D' and P':
// - every original action increases (total-cost) by 1 (at end when
//   durative), and any cost it had is dropped: the metric is the distance
//   alone, not the old metric (makespan is not traded against stability);
// - per occurrence i of O, with schema s and objects a: alplan-keep-i-s, a
//   copy of s with its parameters replaced by a, that needs
//   (alplan-pending-i) and deletes it (at start), adds (alplan-done-i) (at
//   end), and costs nothing; and alplan-forgo-i, instantaneous, from
//   (alplan-pending-i) to (alplan-done-i) at cost 1;
// - P' is P with every (alplan-pending-i) initially true, (total-cost) 0,
//   every (alplan-done-i) in the goal, minimising (total-cost).
//
// With DistanceCounter::Apart (the `adapt` strategy's use, adapt_strategy.cpp)
// the distance is counted in a function of its own, (alplan-distance),
// instead: every original action increases it by 1 and keeps its own
// effects on (total-cost); keep-i keeps the schema's cost effects (bound to
// the occurrence's objects) and adds nothing to the distance; forgo-i adds
// 1 to it; P' sets (alplan-distance) to 0, leaves (total-cost) as P has it
// and keeps P's metric, which the caller weighs the distance into. The same
// contract holds with (alplan-distance) in place of (total-cost).
//
// How this differs from Saetti & Scala's compilation: theirs is for
// classical (STRIPS with costs) actions; ours copies durative actions too,
// with the bookkeeping on the snaps (pending at start, done at end), so a
// kept occurrence is a whole durative action. Their keep actions keep the
// schema's parameters and bind them by equality; ours substitute the
// objects and have no parameters, because the grounder's reachability
// relaxes equality away and would instantiate every binding of every keep
// action before folding all but one away. The planner that solves P' is
// the in-process temporal planner (stable_strategy.cpp says what its search
// guarantees), not a classical optimal planner.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/plan.h"
#include "repair/executing_plan.h"

namespace alplan::repair {

// One occurrence of the old plan: a ground action.
struct OldStep {
  std::string schema;  // lower case, as the AST names it
  std::vector<std::string> args;
  bool operator==(const OldStep&) const = default;
};

// "(schema a b)": how plans and ScheduledAction name a step.
std::string ground_name(const OldStep& step);

// The old plan's steps that start at or after `now`, by start time: what a
// repair at `now` may keep or forgo (steps already started are committed).
std::vector<OldStep> remaining_steps(const ExecutingPlan& plan, double now);

// A copy of `domain` in which (total-cost) is declared, no action changes it
// except that every action increases it by `cost` (at end when durative).
// compile_stability uses cost 1 (TotalCost: every action is a change).
pddl::Domain with_action_cost(const pddl::Domain& domain, double cost);
bool declares_total_cost(const pddl::Domain& domain);
// (= (total-cost) 0) in a copy of `problem`, replacing any value it had.
pddl::Problem with_zero_cost(const pddl::Problem& problem);

// Where the compilation counts the distance. TotalCost (stable): in
// (total-cost), the domain's own costs dropped, the metric the distance
// alone. Apart (adapt): in (alplan-distance), beside the domain's costs and
// the problem's metric, so that a metric such as the home domains'
// (+ (total-time) (total-cost)) still means what it meant.
enum class DistanceCounter { TotalCost, Apart };

struct StableCompilation {
  pddl::Domain domain;
  pddl::Problem problem;
  std::vector<OldStep> old;  // O: occurrence i is old[i]
  std::string distance = "total-cost";  // the function that counts D: total-cost or alplan-distance
  // Compiled action names: keep action -> occurrence, forgo action -> occurrence.
  std::map<std::string, std::size_t> keeps, forgoes;
};

// Throws std::invalid_argument when an occurrence names a schema the domain
// lacks or has the wrong number of objects, or when the domain already
// uses a name beginning with `alplan-` (with Apart, a function's name too).
StableCompilation compile_stability(const pddl::Domain& domain, const pddl::Problem& problem,
                                    const std::vector<OldStep>& old,
                                    DistanceCounter counter = DistanceCounter::TotalCost);

struct MappedPlan {
  Plan plan;  // steps of the original domain, with the compiled plan's times
  std::size_t kept = 0;     // occurrences of O the plan keeps
  std::size_t forgone = 0;  // occurrences it forgoes
  std::size_t added = 0;    // steps that are no kept occurrence
};

// A plan of the compiled task as a plan of the original one: keep steps
// become their occurrence's action, forgo steps are dropped.
MappedPlan map_back(const StableCompilation& compilation, const Plan& compiled);

}  // namespace alplan::repair
