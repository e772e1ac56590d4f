// Searches around the incumbent plan: an anytime engine that improves the
// plan it is given instead of searching from scratch. Two neighbourhoods:
// - States (plan-neighbourhood graph search, Nakhost & Müller, ICAPS 2010):
//   the states the incumbent passes through are its trajectory, every state
//   within `depth` steps of it is the neighbourhood. A plan that skips a
//   step or takes a shortcut between two trajectory states is found there.
//   A round that finds nothing better doubles the depth, as the paper does.
// - Actions: any state, reached by the incumbent's own actions (and timed
//   literals) in any order and number, or within `depth` of its trajectory.
//   In a temporal plan the makespan is mostly the order of the same actions
//   (openstacks: which orders start before which ship), which no state near
//   the trajectory holds: on openstacks 2011 instance 1 the states within
//   depth 2 of a 294-long plan hold nothing shorter, the actions' reorderings
//   a 261 (plan_neighbourhood_search_test.cpp).
// The search inside is weighted A* by steps (g = snaps, h = trpg's count),
// ties to the smaller makespan bound, pruned by the anytime bound. Ordered
// by the metric it found nothing in either neighbourhood on that instance
// (tried once while it was written; no test keeps that): with g the
// makespan so far and h only the relaxed time still to come, it widens
// breadth-first. A round has a budget of expansions (a multiple of
// the incumbent's length): an action neighbourhood is as large as the task
// with the plan's actions. Past `max_depth` or a round with nothing better
// the engine is exhausted.
//
// Temporal states here are POPF's (a state with its running actions); a
// node's schedule comes from the path that reached it, so the neighbourhood
// is a set of states and the search keeps, per state, the schedules that no
// other dominates (SearchSpace). The search is restricted, so its
// exhaustion proves nothing about the task: it only ends a round.
#pragma once

#include <memory>
#include <vector>

#include "planner/search_engine.h"

namespace alplan {

struct NeighbourhoodOptions {
  enum class Kind { States, Actions };
  Kind kind = Kind::States;
  int depth = 1;      // of the first round
  int max_depth = 4;  // rounds double the depth up to this (states)
  double weight = 1.0;
  // A round's expansions: this many per step of the incumbent.
  std::uint64_t expansions_per_step = 50;
  NodeBound prune;  // the anytime bound: nodes that cannot beat the incumbent
  SearchDeadline deadline;
};

// `incumbent` is a plan the search found from `start` (its steps are the
// search's own records, before deordering); the engine keeps a copy.
std::unique_ptr<SearchEngine> make_plan_neighbourhood_search(const TaskIndex& index, const SearchStart& start,
                                                             double epsilon, Heuristic& heuristic,
                                                             const Solution& incumbent,
                                                             NeighbourhoodOptions options);

}  // namespace alplan
