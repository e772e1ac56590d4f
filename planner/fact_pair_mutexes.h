// Pairs of facts that no reachable state holds together: h^2 reachability
// (Haslum & Geffner, "Admissible Heuristics for Optimal Planning", AIPS
// 2000; Bonet & Geffner's mutex reading of it) over the task's actions read
// as classical ones, each durative action compressed into one step that needs
// its start's, invariant's and end's conditions and has both happenings'
// effects.
//
// The compression is what makes these mutexes a heuristic's input rather
// than proven facts of the temporal task: an action running while another
// starts and ends can reach pairs the compressed task cannot. Within the
// compressed task they are sound: numeric and negative conditions are read as
// always true, a conditional effect as adding always and deleting never, a
// timed literal as an action that can happen at any time.
//
// Contract: a pair is reported reachable unless no sequence of compressed
// actions from `start` reaches a state holding both. Tasks with derived
// predicates are not analysed (`analysed()` is false, every pair reachable),
// nor tasks above the work bound of the options, nor past the deadline.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "planner/ground_task.h"

namespace alplan {

// An action of the compressed classical task the analysis reads.
struct CompressedAction {
  std::vector<FactId> pre, add, del;  // sorted; add and del disjoint
};

// Every action, timed literal and conditional effect of the task as
// compressed actions (a conditional effect becomes its action with the
// condition's facts added to the precondition and its adds added).
std::vector<CompressedAction> compress_actions(const GroundTask& task);

struct FactPairMutexOptions {
  // The fixpoint costs actions x facts x precondition facts a round; tasks
  // above this are not analysed.
  std::uint64_t max_work_per_round = 30'000'000;
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

class FactPairMutexes {
 public:
  // Reachability from the facts of `start` (a state, true facts listed).
  FactPairMutexes(const GroundTask& task, const std::vector<FactId>& start,
                  const FactPairMutexOptions& options = {});

  bool analysed() const { return analysed_; }
  bool reachable(FactId f) const { return !analysed_ || single_[f]; }
  bool reachable(FactId f, FactId g) const {
    return !analysed_ || (f == g ? single_[f] : pairs_[index(f, g)]);
  }
  const std::vector<CompressedAction>& actions() const { return actions_; }

 private:
  std::size_t index(FactId f, FactId g) const { return static_cast<std::size_t>(f) * facts_ + g; }
  bool applicable(const CompressedAction& action) const;
  bool round();
  bool mark(FactId f, FactId g);

  std::uint32_t facts_ = 0;
  bool analysed_ = false;
  std::vector<CompressedAction> actions_;
  std::vector<char> single_;
  std::vector<char> pairs_;  // facts_ x facts_, symmetric
};

}  // namespace alplan
