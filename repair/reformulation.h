// Reformulating the planning problem from an observed state (the paper's
// Section 6.3, step 3c): the objects known so far (new ones included), the
// observed atoms and values as the initial state, the timed initial literals
// still to come, the goal and the metric. Actions still running are
// committed: their ends become timed initial literals at the world's
// estimate of when they end, and a value they change continuously starts
// at what it will be then. The result is an ordinary PDDL problem, so the
// same text can go to a planner in another process.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/grounding_cache.h"
#include "planner/planner.h"
#include "repair/executing_plan.h"
#include "repair/world.h"
#include "repair/world_state.h"

namespace alplan::repair {

// `shift` is subtracted from every time (an external planner starts at 0;
// the in-process one plans in the task's own time from `now`): timed
// literals' and the absolute times of PDDL 3 constraints (within,
// hold-during, hold-after), not always-within's span, which is relative.
// The text carries no history: an external planner is asked again for a
// `sometime` the trajectory met already (plan_in_process is told it).
pddl::Problem reformulate(const pddl::Domain& domain, const pddl::Problem& base, const WorldState& observed,
                          const std::vector<ActionInProgress>& in_progress, double now, double shift = 0.0);

// The same shift on PDDL 3 constraints alone: within's, hold-during's and
// hold-after's times move back by `shift`; always-within's span stays.
void shift_constraint_times(pddl::Condition& constraints, double shift);

struct PlanningOutcome {
  std::optional<ExecutingPlan> plan;
  PlannerResult::Status status = PlannerResult::Status::LimitReached;
  std::string message;
  double seconds = 0.0;  // grounding and search
  bool reused_grounding = false;
};

// Grounds a problem, through `cache` when given; `reused` tells whether the
// cache's reference served.
std::shared_ptr<const GroundTask> ground_problem(const pddl::Domain& domain, const pddl::Problem& problem,
                                                 GroundingCache* cache, bool* reused = nullptr);

// Why a repair found no plan, saying what was proved and of what: a proof
// holds for the task as the monitor believes it now (the objects it knows,
// the state it observed), never for the world, where perception may yet see
// something new; a search stopped short proves nothing.
std::string no_plan_reason(PlannerResult::Status status, const std::string& message);

// Grounds the problem (through `cache` when given) and plans from `now`
// with the in-process planner, without the actions of `excluded` schemas.
// `history`: the states believed before `now`, for the problem's PDDL 3
// constraints (what they met or broke already); may be absent.
PlanningOutcome plan_in_process(const pddl::Domain& domain, const pddl::Problem& problem, double now,
                                const PlannerOptions& options, GroundingCache* cache = nullptr,
                                const std::set<std::string>& excluded = {},
                                const std::vector<WorldState>* history = nullptr);

// The task without the ground actions of the named schemas: a view, so that
// one grounding serves a strategy that forbids some actions (suggest).
std::shared_ptr<const GroundTask> without_schemas(std::shared_ptr<const GroundTask> task,
                                                  const std::set<std::string>& excluded);

// The object a name denotes in the problem, with its declared type.
std::optional<std::string> object_type(const pddl::Problem& problem, const std::string& object);

}  // namespace alplan::repair
