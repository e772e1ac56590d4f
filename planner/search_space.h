// The nodes of a temporal search and what engines share: expanding a node
// into scheduled children, evaluating them, recognising goals. A node keeps
// only the step that led to it; its partial plan is rebuilt from the chain
// of parents when needed (POPF keeps states similarly lean).
#pragma once

#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "planner/goal_orders.h"
#include "planner/heuristic.h"
#include "planner/partial_plan.h"
#include "planner/search_state.h"
#include "planner/successor_generator.h"
#include "planner/task_index.h"

namespace alplan {

using NodeId = std::uint32_t;

// Whether a schedule can rule out a future: a timed initial literal, an
// upper bound on a duration (a running action's included), or continuous
// change. Otherwise every sequence of applicable snaps can be scheduled.
bool schedules_can_close_doors(const GroundTask& task, const SearchState& start);

// What of a node's schedule decides which futures remain feasible: how late
// each running action may still end, and (with deadlines) how late the plan
// has already got. POPF compares states without it and can lose plans; we
// prune a node only when a stored node with the same state is at least as
// good here (dominance).
struct TemporalSignature {
  double frontier = 0.0;
  std::vector<double> latest_ends;  // in the order of state.running()
};

struct SearchNode {
  NodeId parent = kNoId;
  StepRecord step;  // the step from the parent; meaningless at the root
  SearchState state;
  double h = std::numeric_limits<double>::infinity();
  std::uint32_t depth = 0;
  double makespan = 0.0;
  // A lower bound on the makespan of any plan through this node: its own
  // makespan, or when the goals are reached in the relaxation (known once
  // evaluated). Anytime search prunes on it.
  double makespan_bound = 0.0;
  double relaxed_cost = 0.0;  // the heuristic's estimate of the metric still to come
  TemporalSignature signature;
  // With exact duplicates: what the schedule allows of every future step.
  std::shared_ptr<const PartialPlan::Interface> interface;
  std::vector<Snap> helpful;
  // False while the node carries its parent's h (deferred evaluation).
  bool evaluated = false;
};

struct SearchStatistics {
  std::uint64_t expanded = 0, evaluated = 0, generated = 0, duplicates = 0, unschedulable = 0, dead_ends = 0;

  SearchStatistics& operator+=(const SearchStatistics& s) {
    expanded += s.expanded;
    evaluated += s.evaluated;
    generated += s.generated;
    duplicates += s.duplicates;
    unschedulable += s.unschedulable;
    dead_ends += s.dead_ends;
    return *this;
  }
};

// The start of a search: the initial state of the task, or an observed state
// with actions still running (replanning, issue 5).
struct SearchStart {
  SearchState state;
  double release = 0.0;  // no new step before this time
};

struct Solution {
  std::vector<StepRecord> steps;
  std::vector<double> times;  // each step's time, epsilon kept where free (PartialPlan::preferred_times)
  double makespan = 0.0;      // of those times
  // The goal node as the search measured it (earliest times, no gap where
  // none is needed): what an anytime bound compares other nodes with, so
  // that the same plan found again is pruned.
  double search_makespan = 0.0;
  SearchState final_state;
};

// A child of an expanded node, scheduled but not yet stored.
struct Child {
  SearchNode node;
  PartialPlan plan;
};

// How a search space treats what a search that must not miss a plan cannot
// afford to drop. The defaults are POPF's, which lose plans in corner cases
// for speed; a proving search (search_engine.h, `complete`) turns all on.
struct SearchSpaceOptions {
  // An action may run twice at once (successor_generator.h).
  bool self_overlap = false;
  // A guiding dead end is pruned only if the sound relaxation confirms it
  // (temporal_rpg.h, Relaxation); otherwise the node keeps the sound h.
  bool confirm_dead_ends = false;
  // Where schedules can close doors (timed literals, durations bounded
  // above), a node is a duplicate only if a stored node with its state
  // allows every future its schedule allows (PartialPlan::interface):
  // POPF's comparison of states alone, and our cheaper dominance on the
  // running actions' latest ends, can drop the only schedule that works.
  bool exact_duplicates = false;
  // A start whose invariant another start of its happening gives (VAL
  // checks invariants after the start's happening) is searched: a holder
  // started with its provider (successor_generator.h, `pending`). It
  // widens the branching where one action's start gives another's
  // invariant (storage's lift and drop: 1.6x the states on instance 5).
  bool simultaneous_invariants = false;
};

class SearchSpace {
 public:
  SearchSpace(const TaskIndex& index, const SearchStart& start, double epsilon, SearchSpaceOptions options = {});

  NodeId root() const { return 0; }
  const SearchNode& node(NodeId id) const { return nodes_[id]; }
  SearchNode& node(NodeId id) { return nodes_[id]; }
  std::size_t size() const { return nodes_.size(); }

  PartialPlan partial_plan(NodeId id) const;
  // Every applicable snap of a node that can be scheduled, as children.
  std::vector<Child> children(NodeId id, const PartialPlan& plan, SearchStatistics& stats) const;
  // The same in two halves, for a search that looks at children one at a
  // time and stops early (EHC): scheduling (a copy of the partial plan and
  // an STN update) is most of a child's cost, so it is paid only for the
  // children looked at.
  std::vector<Successor> successors(NodeId id, SearchStatistics& stats) const;
  std::optional<Child> schedule(NodeId id, const PartialPlan& plan, Successor successor,
                                SearchStatistics& stats) const;
  // Evaluates a child; false for a dead end.
  bool evaluate(Child& child, Heuristic& heuristic, SearchStatistics& stats) const;
  // The same for a node stored unevaluated (deferred evaluation).
  bool evaluate_stored(NodeId id, const PartialPlan& plan, Heuristic& heuristic, SearchStatistics& stats);
  // Stores a child unless a stored node with its state dominates it.
  std::optional<NodeId> insert(Child child, SearchStatistics& stats);
  // Whether insert() would drop the child as a duplicate (counted then):
  // the state and its timing are known before the heuristic is, so engines
  // ask first and evaluate only new children.
  bool known(const Child& child, SearchStatistics& stats) const;
  void set_root_heuristic(Heuristic& heuristic, SearchStatistics& stats);
  // The stored node with this state, if any.
  std::optional<NodeId> find(const SearchState& state) const;

  // A node is a goal when nothing runs and, once the remaining timed literals
  // are applied (PDDL 2.2 checks the goal after them), the goal holds and
  // the schedule is still consistent.
  std::optional<Solution> goal_reached(NodeId id, const PartialPlan& plan) const;

  const TaskIndex& index() const { return index_; }
  double epsilon() const { return epsilon_; }
  // Children that break one of these goal orders are dead ends here, before
  // the heuristic is asked (planner/goal_orders.h); null: none.
  void prune_by(std::shared_ptr<const GoalOrders> orders) { orders_ = std::move(orders); }

 private:
  const TaskIndex& index_;
  SuccessorGenerator successors_;
  double epsilon_;
  double release_;
  bool dominated(const SearchNode& candidate, NodeId stored) const;
  bool timed_literals_remain(const SearchState& state) const;
  static TemporalSignature signature_of(const SearchState& state, const PartialPlan& plan);
  bool evaluate_node(SearchNode& node, const PartialPlan& plan, Heuristic& heuristic, SearchStatistics& stats) const;

  SearchSpaceOptions options_;
  bool deadlines_;  // the task has timed initial literals
  // Exact duplicates are needed only where a schedule can close a door.
  bool schedules_matter_;
  std::shared_ptr<const GoalOrders> orders_;
  std::deque<SearchNode> nodes_;
  std::unordered_map<const SearchState*, std::vector<NodeId>, SearchStateHash, SearchStateEqual> seen_;
};

}  // namespace alplan
