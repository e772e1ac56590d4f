// Orders among the goal's facts that every plan keeps: a goal g comes before
// a goal g' when g' is never deleted and g cannot be achieved in any state
// holding g' (Koehler & Hoffmann, "On Reasonable and Forced Goal Orderings
// and their Use in an Agenda-Driven Planning Algorithm", JAIR 2000). Read
// from h^2 mutexes (planner/fact_pair_mutexes.h): every achiever of g needs
// a fact mutex with g'. Orders found feed the next round, as Koehler and
// Hoffmann's obedient orders do: when g'' must precede g, an achiever of g
// must also leave a state holding g'' (it adds g'' or its precondition can
// hold beside g'').
//
// A state holding g' without g is then a dead end that the delete
// relaxation may not see: in floor-tile a painted tile cannot be stood on,
// so painting a row before the one above it walls the upper row off, and
// the relaxed plan, which stands on tiles it has already painted, counts it
// reachable (benchmarks/README.md, floor-tile 2014).
//
// Contract: the orders are sound for the compressed classical task the
// mutexes are read from, not proven for the temporal one (an action running
// across another can reach what the compressed task cannot), so the planner
// prunes with them only in some of its engines (planner/planner.cpp), and a
// search that prunes with them proves nothing by exhausting. Only goals false
// in the start and never deleted by any action or timed literal are ordered.
// Contract of broken_by: a state breaks an order only if the order's `after`
// holds or is pending while its `before` is neither.
#pragma once

#include <optional>
#include <vector>

#include "planner/fact_pair_mutexes.h"
#include "planner/ground_task.h"
#include "planner/search_state.h"

namespace alplan {

struct GoalOrder {
  FactId before = kNoId, after = kNoId;
  bool operator==(const GoalOrder&) const = default;
};

struct GoalOrderOptions {
  std::size_t max_goals = 400;  // more goals are not ordered (the rounds cost goals^2)
  FactPairMutexOptions mutexes;
};

class GoalOrders {
 public:
  // Orders for a search from the facts `start` (nothing running).
  GoalOrders(const GroundTask& task, const std::vector<FactId>& start, const GoalOrderOptions& options = {});

  const std::vector<GoalOrder>& orders() const { return orders_; }
  bool empty() const { return orders_.empty(); }
  // An order the state breaks, if any: its `after` holds or a running
  // action's end will add it, and its `before` neither holds nor will be
  // added so. Pending ends count because the wall goes up when the second
  // painting starts, not when it ends; a `before` still being painted keeps
  // the state alive, since both may end in either order.
  std::optional<GoalOrder> broken_by(const SearchState& state) const;

 private:
  std::vector<GoalOrder> orders_;
  std::vector<std::vector<FactId>> goals_added_at_end_;  // by action: the ordered goals its end adds
};

}  // namespace alplan
