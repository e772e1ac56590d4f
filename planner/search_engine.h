// Search engines are components chosen by name (Fast Downward's habit): each
// advances by step() — one expansion — so the caller can stop it at a time
// limit, and reports the first solution it finds.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "planner/linear_metric.h"
#include "planner/search_space.h"

namespace alplan {

enum class SearchStatus { InProgress, Solved, Exhausted };

// Prunes nodes that cannot beat the best plan so far (anytime search).
using NodeBound = std::function<bool(const SearchNode&)>;

// When a step must stop: on a large task one expansion evaluates dozens of
// children at tens of milliseconds each, so a time limit checked only
// between steps would be overrun by seconds. A step that meets its deadline
// returns InProgress at once, and its caller stops the search.
using SearchDeadline = std::optional<std::chrono::steady_clock::time_point>;
inline bool passed(const SearchDeadline& deadline) {
  return deadline && std::chrono::steady_clock::now() > *deadline;
}

class SearchEngine {
 public:
  virtual ~SearchEngine() = default;
  virtual SearchStatus step() = 0;
  virtual std::string name() const = 0;
  const std::optional<Solution>& solution() const { return solution_; }
  const SearchStatistics& statistics() const { return stats_; }
  // Nodes the engine stores in spaces of its own, beyond the space it was
  // given (counted against the node limit).
  virtual std::size_t stored_elsewhere() const { return 0; }

 protected:
  std::optional<Solution> solution_;
  SearchStatistics stats_;
};

struct BestFirstOptions {
  // f = g + weight * h with g the number of snaps; weight 0 means greedy
  // (f = h, ties broken by g).
  double weight = 0.0;
  // Set (weighted A* only): g is the metric's value at the node and h the
  // heuristic's estimate of the metric still to come, in the metric's units;
  // step counts only break ties. The heuristic must have been built with the
  // same metric, or h_metric is the makespan part alone.
  std::shared_ptr<const LinearMetric> metric;
  // Expand helpful children from their own queue, alternating with the
  // main one (Richter & Helmert's preferred operators).
  bool preferred_queue = true;
  // Evaluate a node when it is expanded, not when it is generated (not
  // with a metric order, whose goal test needs h at generation).
  bool deferred = false;
  // A third queue drawing nodes at random by type (h, g), every fourth
  // expansion (planner/type_bucket_queue.h); not with a metric order.
  bool type_exploration = false;
  std::uint64_t seed = 0;  // the type-based queue's draws
  // Greedy only: the queues order nodes by (novelty, h), novelty of width 1
  // within the node's h (planner/novelty_table.h), instead of by h alone.
  bool novelty = false;
  int novelty_width = 1;
  // Among nodes equal in f and h, the one whose plan can end soonest goes
  // first: its makespan bound, the partial plan's makespan or the time the
  // relaxation reaches the goals (the relaxed plan's critical path, which
  // OPTIC and TFD read for makespan). With h a count of snaps, ties are
  // the rule (a step that waits for a long action counts as one that does
  // not), and first in, first out among them chains steps in the order they
  // were generated, as EHC did before EhcOptions::makespan_first.
  bool makespan_ties = false;
  // A search that must not miss a plan: every node is tested for the goal
  // (not only where h = 0, which a heuristic that is not goal-aware could
  // hide), and no queue draws at random. Its search space must keep what it
  // cannot afford to drop (SearchSpaceOptions).
  bool complete = false;
  NodeBound prune;
  SearchDeadline deadline;
};

struct EhcOptions {
  // With helpful children to try, the others are never tried (POPF's rule).
  bool helpful_only = true;
  // Try a node's helpful children in the order of the makespan each gives
  // the partial plan, shortest first, rather than in the order they were
  // generated. EHC takes the first child that lowers h; where many lower it
  // equally (a relaxed plan of steps counts a step that waits for a long
  // action like one that does not), the first generated decides how the
  // plan's steps are chained, and a step chained before it has to wait
  // delays every later step on the same chain (openstacks: a shipment read
  // the stack counter before the last orders were started, so every later
  // order waited 55 time units for it; first plans 294 -> 133). Scheduling
  // every helpful child costs an STN update each, never an evaluation.
  bool makespan_first = true;
  SearchDeadline deadline;
};

// Enforced hill-climbing (Hoffmann & Nebel 2001) over helpful snaps, as
// POPF's first search: breadth-first from the best node until a child has a
// strictly smaller h. Exhausted when a plateau has no exit.
std::unique_ptr<SearchEngine> make_enforced_hill_climbing(SearchSpace& space, Heuristic& heuristic,
                                                          EhcOptions options = {});
// Greedy best-first search or weighted A*.
std::unique_ptr<SearchEngine> make_best_first_search(SearchSpace& space, Heuristic& heuristic,
                                                     BestFirstOptions options);

}  // namespace alplan
