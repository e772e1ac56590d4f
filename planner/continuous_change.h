// Linear continuous change (PDDL 2.1 level 4) as COLIN plans with it (Coles,
// Coles, Fox & Long, "COLIN: Planning with Continuous Linear Numeric
// Change", JAIR 44, 2012). While a durative action runs, each of its
// continuous effects moves a variable at a rate fixed when it starts, so a
// changing variable's value at any step is linear in the steps' times; the
// search cannot know it from the state alone, and conditions on it become
// linear constraints on the schedule (continuous_schedule.h).
//
// This file holds what is fixed per task: which variables change with time
// (those with continuous effects, and those discrete effects compute from
// them), and the translation of a snap's conditions, duration constraints
// and effects on such variables into linear forms over their values at the
// snap's time and ?duration, every other term evaluated in the state the
// snap is applied in.
//
// Contract: a task without continuous effects has no ContinuousModel (the
// planner then behaves exactly as without this file). What is not linear
// (a product of two changing terms, a division by one, a rate that depends
// on a changing variable, a conditional effect on one) is refused by name.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/formula_evaluation.h"
#include "planner/ground_task.h"
#include "planner/search_state.h"
#include "planner/snap_action.h"

namespace alplan {

// constant + sum coefficient * value(variable) + duration_coefficient * ?duration
struct LinearForm {
  double constant = 0.0;
  std::vector<std::pair<NumericVarId, double>> terms;
  double duration = 0.0;
};

// form (comparison) 0
struct LinearCondition {
  LinearForm form;
  pddl::Comparison comparison = pddl::Comparison::GreaterEqual;
  std::string text;  // the condition as written, for messages
};

struct LinearAssignment {
  NumericVarId variable = kNoId;
  pddl::AssignOperator assign = pddl::AssignOperator::Assign;
  LinearForm value;
};

// What a snap does to and asks of the changing variables.
struct ContinuousStep {
  std::vector<LinearCondition> conditions;  // at the snap, before its effects
  std::vector<LinearCondition> invariants;  // a start: its over-all conditions, until its end
  std::vector<LinearAssignment> effects;    // discrete effects on changing variables
  std::vector<std::pair<NumericVarId, double>> rates;  // a start: change per time unit, signed
  bool empty() const { return conditions.empty() && invariants.empty() && effects.empty() && rates.empty(); }
};

// Each continuous effect's variable and change per time unit (negative for
// a decrease), fixed in the state the action starts in, before its start's
// effects (PDDL 2.1 level 4). The planner, the validator and the simulated
// world all read rates through this. Throws EvaluationError on an
// undefined rate.
template <typename State>
std::vector<std::pair<NumericVarId, double>> signed_rates(const GroundAction& action, const State& state,
                                                          double duration) {
  std::vector<std::pair<NumericVarId, double>> rates;
  EvaluationContext context;
  context.duration = duration;
  for (const ContinuousEffect& c : action.continuous) {
    const double rate = evaluate(c.rate, state, context);
    rates.emplace_back(c.variable, c.assign == pddl::AssignOperator::Decrease ? -rate : rate);
  }
  return rates;
}

class ContinuousModel {
 public:
  // Null when the task has no continuous effect.
  static std::shared_ptr<const ContinuousModel> build(const GroundTask& task);

  bool changing(NumericVarId v) const { return changing_[v]; }
  bool changing(const GroundExpression& e) const;
  bool changing(const GroundComparison& c) const { return changing(c.left) || changing(c.right); }
  // The first construct the planner cannot schedule, with the action's name.
  const std::optional<std::string>& unsupported() const { return unsupported_; }

  // The snap's part on changing variables; nullopt when a value it needs is
  // undefined in `before` (the snap is then not applicable). `duration` is
  // the duration when fixed (NaN otherwise).
  std::optional<ContinuousStep> step(const GroundAction& action, SnapKind kind, const SearchState& before,
                                     double duration) const;
  // The goal's comparisons on changing variables.
  std::optional<std::vector<LinearCondition>> goal(const ConditionSet& goal, const SearchState& state) const;

  // Which ends of a changing variable's range the heuristic needs: for each
  // condition of an action or the goal on it that fails in `state`, the
  // least value if a smaller one would help, the greatest if a larger one
  // would. Each end costs the schedule a linear program.
  struct NeededBounds {
    bool least = false, greatest = false;
  };
  NeededBounds needed_bounds(NumericVarId v, const SearchState& state) const;
  // The actions that change a variable, continuously or at a snap.
  const std::vector<ActionId>& writers(NumericVarId v) const { return writers_[v]; }

  // Whether a condition holds, its comparisons on changing variables left
  // to the schedule.
  bool holds_fixed_part(const ConditionSet& c, const SearchState& state, double duration) const;

 private:
  explicit ContinuousModel(const GroundTask& task);
  void check_linear(const GroundTask& task);
  void index_readers_and_writers(const GroundTask& task);

  const GroundTask* task_;
  std::vector<bool> changing_;
  std::vector<std::vector<const GroundComparison*>> comparisons_;  // by changing variable
  std::vector<std::vector<ActionId>> writers_;                     // by changing variable
  std::optional<std::string> unsupported_;
};

}  // namespace alplan
