// Backward relevance analysis: the ground actions that can contribute to
// the goal. A fact is relevant when the goal or a relevant action's
// condition names it (a derived fact: its axioms' bodies too); an action is
// relevant when it adds a fact a condition needs true, deletes one a
// condition needs false, or changes a numeric variable a condition, a
// duration or the metric reads. The rest can only be left out of a plan:
// removing an action whose effects no relevant condition reads keeps every
// other step's conditions as they were, so every plan of the pruned task is
// a plan of the whole one, and the whole one's plans shrink to plans of the
// pruned one. Fast Downward's translator does the same on finite-domain
// variables (Helmert, "Concise finite-domain representations for PDDL
// planning tasks", AIJ 2009, relevance analysis).
//
// Why it matters: a home's task grounds every robot giving every object to
// every senior (40 thousand `give` actions for 40 seniors), while a goal
// names one senior and one kind of remedy; the temporal RPG pays for every
// reachable action at every evaluation.
//
// Conservative where the analysis would need care: every condition of a
// relevant action counts, a conditional effect's both ways (it may be
// unwanted, its condition then made false first), a derived fact makes its
// bodies relevant both ways, a general formula's literals count both ways,
// and the metric's variables count unless the metric only grows as a plan
// grows (linear_metric.h: action costs). PDDL 3: every fact a trajectory
// constraint names (hard or soft) counts both ways, and a preference's
// condition as a condition, so an action needed only to keep an `always`
// true stays (issue 44: pruning it made a one-step task time out).
#pragma once

#include <memory>
#include <vector>

#include "planner/ground_task.h"
#include "planner/ids.h"

namespace alplan {

// Per action: true where it can contribute to the goal. `keep` (actions
// running in the state planned from) are relevant whatever they do.
std::vector<bool> relevant_actions(const GroundTask& task, const std::vector<ActionId>& keep = {});

// The task with only its relevant actions: a view sharing everything but
// the action list. `new_id[a]` is the view's id of the task's action `a`
// (kNoId where pruned). `pruned` is 0 when the view is the task itself.
struct RelevantView {
  std::shared_ptr<const GroundTask> task;
  std::vector<ActionId> new_id;
  std::size_t pruned = 0;
};

RelevantView relevant_view(const std::shared_ptr<const GroundTask>& task, const std::vector<ActionId>& keep = {});

// The same pruning for a task that shares its ground actions and goal with
// the one `like` was made from (a grounding cache's derived tasks): the
// view's actions are `like`'s very vector, so indexes built on it serve.
RelevantView relevant_view_like(const std::shared_ptr<const GroundTask>& task, const RelevantView& like);

}  // namespace alplan
