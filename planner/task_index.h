// Read-only tables the search computes once per GroundTask: each snap's
// footprint, an index of actions by one positive precondition (so that the
// successors of a state are found from its true facts, not by trying every
// action), which actions have effects that depend on ?duration, and which
// constructs the planner cannot handle.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/continuous_change.h"
#include "planner/ground_task.h"
#include "planner/snap_action.h"

namespace alplan {

class TaskIndex {
 public:
  explicit TaskIndex(std::shared_ptr<const GroundTask> task);
  // The same index for a task that shares its ground actions, fact table
  // size and axioms with `like`'s (a GroundingCache's derived task): the
  // action tables are shared, only the timed literals' footprints are new.
  // Any other task is indexed from scratch.
  TaskIndex(std::shared_ptr<const GroundTask> task, const TaskIndex& like);

  const GroundTask& task() const { return *task_; }
  const std::shared_ptr<const GroundTask>& task_pointer() const { return task_; }

  const Footprint& footprint(Snap snap) const;
  // With `quiet`, the footprint of the snap where none of its conditional
  // effects fires (their conditions read first, Footprint::reads_first;
  // their effects left out): VAL counts a condition read only where it
  // holds. The same as footprint(snap) for a snap without any.
  const Footprint& footprint(Snap snap, bool quiet) const;
  // Actions whose at-start (instantaneous: whole) precondition contains the
  // fact; every action is listed under exactly one fact, or in unindexed().
  const std::vector<ActionId>& indexed_by(FactId fact) const { return actions_->by_fact[fact]; }
  const std::vector<ActionId>& unindexed() const { return actions_->unindexed; }
  // Effects or conditions read ?duration: the duration must be fixed at start.
  bool duration_dependent(ActionId action) const { return actions_->duration_dependent[action]; }
  // Continuous change (PDDL 2.1 level 4): null when the task has none.
  const std::shared_ptr<const ContinuousModel>& continuous() const { return actions_->continuous; }
  // A durative action's conditional effects whose condition reads a key
  // its other snap writes (indices into start.conditional and
  // end.conditional). Where its duration is 0 its start and end form one
  // happening, in which VAL reads such a condition in the state before and
  // counts it as read only when it holds (Action::handleEffects): the
  // search requires each to be false there, and a zero-duration end never
  // fires its own (successor_generator.cpp).
  struct CrossConditionals {
    std::vector<std::uint32_t> start, end;
    Footprint start_footprint, end_footprint;  // the snaps' footprints without these effects
  };
  const CrossConditionals* cross_conditionals(ActionId action) const;
  // The key a snap that must be alone in its happening writes and every
  // snap reads (task_index.cpp, must_be_alone); none where no snap must.
  std::optional<std::uint32_t> alone_key() const { return actions_->alone_key; }
  // Quiet footprints (footprint(snap, true)) of the snaps that have
  // conditional effects, sorted by action.
  struct QuietFootprints {
    std::vector<std::pair<ActionId, Footprint>> instant, start, end;
  };
  // The first construct of the task the planner refuses, with its position.
  const std::optional<std::string>& unsupported() const { return unsupported_; }

 private:
  struct ActionTables {
    std::vector<Footprint> instant, start, end;
    std::vector<std::vector<ActionId>> by_fact;
    std::vector<ActionId> unindexed;
    std::vector<bool> duration_dependent;
    std::optional<std::string> unsupported;
    std::shared_ptr<const ContinuousModel> continuous;
    std::vector<std::pair<ActionId, CrossConditionals>> cross;  // sorted by action
    QuietFootprints quiet;
    // Set where some snap must be alone in its happening (task_index.cpp,
    // must_be_alone): every footprint reads it, such snaps write it.
    std::optional<std::uint32_t> alone_key;
  };
  static std::shared_ptr<const ActionTables> index_actions(const GroundTask& task);
  static void mark_alone_snaps(const GroundTask& task, ActionTables& tables);
  static std::uint32_t alone_key_of(const GroundTask& task);
  void index_rest();

  std::shared_ptr<const GroundTask> task_;
  std::shared_ptr<const ActionTables> actions_;
  std::vector<Footprint> til_;
  std::optional<std::string> unsupported_;
};

}  // namespace alplan
