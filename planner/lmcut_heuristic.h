// The landmark-cut heuristic (Helmert & Domshlak, "Landmarks, critical
// paths and abstractions: what's the difference anyway?", ICAPS 2009), on
// the delete relaxation of a temporal task's whole actions: an admissible
// estimate of the metric still to come, for a search that must prove its
// plan cost-optimal (the `stable` repair's minimum-distance plans, whose
// uniform-cost search drowned in the interleavings of zero-cost steps).
//
// The relaxation, and why it never overestimates. Each ground action is one
// relaxed operator: its at-start facts, and its over-all and at-end facts
// that its own start does not add, as preconditions; every fact it adds at
// either end, conditional adds included, as effects; its cost what its
// unconditional effects add to the metric at both ends (LinearMetric: the
// metric is monotone, so a conditional effect can only add more). An
// action running in the state contributes its end as a free operator and
// its end's cost as owed: the goal is a state with nothing running, so
// every plan from here pays it, and no operator of the relaxed task does.
// Axioms are free operators; a fact a timed initial literal will add is
// free from the start; negative and numeric conditions, durations, windows
// and deletes are dropped. Every plan from the state therefore contains a
// relaxed plan of the operators it starts, so the cost of those is at least
// h+ >= LM-cut, and the remaining metric is at least owed + LM-cut. A goal
// the relaxation never reaches is a proof that the state is a dead end
// (the relaxation only adds), in either Relaxation mode.
//
// Without a metric the operators cost 1 each: the estimate counts actions
// still to start. `HeuristicValue::h` is 0 at a goal with nothing running,
// else 1 + the estimate (so a search orders on it where it breaks ties).
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "planner/heuristic.h"
#include "planner/linear_metric.h"
#include "planner/task_index.h"

namespace alplan {

class LmCutHeuristic : public Heuristic {
 public:
  // `metric` may be null: unit costs.
  LmCutHeuristic(const TaskIndex& index, std::shared_ptr<const LinearMetric> metric);
  HeuristicValue evaluate(const SearchState& state, const PartialPlan& plan,
                          Relaxation mode = Relaxation::Guiding) override;
  std::vector<FactId> unreached_goals() const override { return unreached_; }

  // The estimate of the metric still to come from `state` (owed ends
  // included), or infinity at a dead end: what evaluate puts in `cost`.
  double estimate(const SearchState& state);

 private:
  using Node = std::uint32_t;  // a fact, or one of the two artificial ones
  struct Operator {
    std::vector<Node> pre, add;
    double base_cost = 0.0;
    ActionId action = kNoId;  // the action a running end belongs to; kNoId otherwise
  };
  void add_operator(std::vector<Node> pre, std::vector<Node> add, double cost, ActionId running_end);
  bool compute_hmax();  // false when the goal is unreachable
  double cut_once();    // adds the cut's cost, returns it (0 once the goal costs nothing)

  const TaskIndex& index_;
  std::shared_ptr<const LinearMetric> metric_;
  Node start_node_ = 0, goal_node_ = 0;
  std::vector<Operator> operators_;
  std::vector<std::vector<std::uint32_t>> precondition_of_, achievers_;
  std::vector<std::uint32_t> end_operator_;  // per action: its running end's operator, or kNoId
  std::vector<Node> til_adds_;
  // Per evaluation.
  std::vector<double> cost_, hmax_, op_value_;
  std::vector<std::uint32_t> unsatisfied_, pcf_;
  std::vector<char> enabled_, root_, zone_, reached_, in_cut_;
  std::vector<Node> roots_, work_;
  std::vector<std::uint32_t> cut_;
  using HeapEntry = std::pair<double, Node>;
  std::vector<HeapEntry> heap_;
  std::vector<FactId> unreached_;
};

}  // namespace alplan
