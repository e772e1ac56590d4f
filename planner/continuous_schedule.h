// The schedule of a partial plan with continuous change, as COLIN builds it
// (Coles et al., JAIR 2012, section 5): the simple temporal network's
// constraints plus, for every condition a step places on a changing
// variable, a linear constraint on the steps' times, all solved as one
// linear program (CLP). A changing variable's value is kept as an affine
// function of the time points: base + gradient x now, where `base` is
// linear in the times of the steps so far and `gradient` is the sum of the
// rates of the actions changing it that are still running.
//
// Over-all conditions are checked before and after every step that changes
// a variable they read: between two such steps the value is linear, so its
// extremes are at those steps (the plan's ordering puts every writer of a
// variable in sequence). The linear program minimises the sum of the times,
// so each step is as early as the constraints let it be.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "planner/continuous_change.h"
#include "planner/linear_program.h"
#include "planner/simple_temporal_network.h"
#include "planner/snap_action.h"

namespace alplan {

// Where a snap sits in the network.
struct SnapNodes {
  SnapKind kind = SnapKind::Instant;
  ActionId action = kNoId;
  std::uint32_t node = 0;        // the snap's time point
  std::uint32_t start_node = 0;  // durative: its start's and its end's
  std::uint32_t end_node = 0;
};

class ContinuousSchedule {
 public:
  ContinuousSchedule(std::shared_ptr<const ContinuousModel> model, const std::vector<double>& initial_values);

  // The changing variables an over-all condition of a running action reads
  // that the snap makes this schedule check at its time: the partial plan
  // orders the snap against their writers as if it read them.
  std::vector<NumericVarId> invariant_reads(const ContinuousStep& step, const SnapNodes& at) const;

  // Adds the snap's constraints and effects; false (and no change) when the
  // network and the linear constraints cannot all hold.
  // `solve` false: the caller knows the constraints hold (a replay) and
  // solves once at the end with resolve().
  bool add(const ContinuousStep& step, const SnapNodes& at, const SimpleTemporalNetwork& network, bool solve = true);
  // Conditions that must hold once every step is done (the goal's).
  bool require_final(const std::vector<LinearCondition>& conditions, const SimpleTemporalNetwork& network);
  // The schedule again after the network alone changed (a timed literal).
  bool resolve(const SimpleTemporalNetwork& network);

  // Whether times come from the linear program rather than the network.
  bool active() const { return !rows_.empty(); }
  double time(std::uint32_t node) const { return times_[node]; }
  // A changing variable's value at a node's time in the current solution.
  double value_at(NumericVarId v, std::uint32_t node) const;
  // The time point of the last step that changed the variable (its value
  // right after it is the variable's value "now": a later step not ordered
  // after its next change would extrapolate past it); 0 when none has.
  std::uint32_t last_change(NumericVarId v) const { return last_change_[v]; }
  // The least and greatest value a changing variable can have at a node's
  // time over every schedule the constraints allow (COLIN's bounds, which
  // its heuristic starts from); infinite where unbounded.
  // Only the ends asked for are computed; the others stay at the value.
  std::pair<double, double> bounds(NumericVarId v, std::uint32_t node, const SimpleTemporalNetwork& network,
                                   bool least = true, bool greatest = true) const;
  std::size_t rows() const { return rows_.size(); }
  // Running actions whose over-all conditions cannot hold at their ends if
  // nothing changes the rates and values from now on, with the variables
  // those conditions read: unless another action changes one of them before
  // the end, the plan cannot be finished.
  std::vector<std::pair<ActionId, std::vector<NumericVarId>>> failing_at_end(
      const SimpleTemporalNetwork& network) const;

 private:
  struct Affine {
    double constant = 0.0;
    std::vector<std::pair<std::uint32_t, double>> terms;  // node, coefficient
    void add(std::uint32_t node, double coefficient);
    void add(const Affine& other, double k);
  };
  struct Trajectory {
    Affine base;
    double gradient = 0.0;
  };
  struct Running {
    ActionId action = kNoId;
    std::vector<LinearCondition> invariants;
    std::vector<std::pair<NumericVarId, double>> rates;
    std::uint32_t start_node = 0, end_node = 0;
  };

  Affine at(NumericVarId v, std::uint32_t node) const;
  Affine evaluate(const LinearForm& form, std::uint32_t node, const SnapNodes& at) const;
  void require(const LinearCondition& c, std::uint32_t node, const SnapNodes& at);
  void check_invariants(const std::vector<NumericVarId>& written, const SnapNodes& at, ActionId except);
  bool apply_effects(const std::vector<LinearAssignment>& effects, const SnapNodes& at);
  // `least`: the least schedule, not only a feasible one.
  bool solve(const SimpleTemporalNetwork& network, bool least = false);
  std::optional<std::vector<double>> pushed_schedule(const SimpleTemporalNetwork& network) const;
  LinearProgram program(const SimpleTemporalNetwork& network) const;
  bool satisfied_by(const std::vector<double>& times) const;
  static bool rows_satisfied(const std::vector<LinearRow>& rows, const std::vector<double>& times);
  // Whether the constraints so far and `extra` can all hold.
  bool feasible_with(const std::vector<LinearRow>& extra, const SimpleTemporalNetwork& network) const;
  LinearRow row_for(const LinearCondition& c, std::uint32_t node, const SnapNodes& at) const;

  std::shared_ptr<const ContinuousModel> model_;
  std::vector<Trajectory> values_;  // by variable; only changing ones are used
  std::vector<std::uint32_t> last_change_;  // by variable
  std::vector<Running> running_;
  std::vector<LinearRow> rows_;     // over network nodes
  std::vector<double> times_;
};

}  // namespace alplan
