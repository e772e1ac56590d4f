// The blind heuristic: 0 where the goal's facts hold, 1 elsewhere; no dead
// end, no helpful snap. The baseline a planning researcher compares against,
// and with a complete weighted A* at w=1 a uniform-cost search over snaps.
#pragma once

#include "planner/heuristic.h"
#include "planner/task_index.h"

namespace alplan {

class BlindHeuristic : public Heuristic {
 public:
  explicit BlindHeuristic(const TaskIndex& index) : index_(index) {}
  HeuristicValue evaluate(const SearchState& state, const PartialPlan& plan,
                          Relaxation mode = Relaxation::Guiding) override;
  std::vector<FactId> unreached_goals() const override { return {}; }

 private:
  const TaskIndex& index_;
};

}  // namespace alplan
