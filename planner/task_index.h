// Read-only tables the search computes once per GroundTask: each snap's
// footprint, an index of actions by one positive precondition (so that the
// successors of a state are found from its true facts, not by trying every
// action), which actions have effects that depend on ?duration, and which
// constructs the planner cannot handle.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/ground_task.h"
#include "planner/snap_action.h"

namespace alplan {

class TaskIndex {
 public:
  explicit TaskIndex(std::shared_ptr<const GroundTask> task);

  const GroundTask& task() const { return *task_; }
  const std::shared_ptr<const GroundTask>& task_pointer() const { return task_; }

  const Footprint& footprint(Snap snap) const;
  // Actions whose at-start (instantaneous: whole) precondition contains the
  // fact; every action is listed under exactly one fact, or in unindexed().
  const std::vector<ActionId>& indexed_by(FactId fact) const { return by_fact_[fact]; }
  const std::vector<ActionId>& unindexed() const { return unindexed_; }
  // Effects or conditions read ?duration: the duration must be fixed at start.
  bool duration_dependent(ActionId action) const { return duration_dependent_[action]; }
  // The first construct of the task the planner refuses, with its position.
  const std::optional<std::string>& unsupported() const { return unsupported_; }

 private:
  std::shared_ptr<const GroundTask> task_;
  std::vector<Footprint> instant_, start_, end_, til_;
  std::vector<std::vector<ActionId>> by_fact_;
  std::vector<ActionId> unindexed_;
  std::vector<bool> duration_dependent_;
  std::optional<std::string> unsupported_;
};

}  // namespace alplan
