#include "planner/numeric_effect_analysis.h"

#include <cmath>
#include <limits>

#include "planner/formula_evaluation.h"

namespace alplan {
namespace {

using Kind = GroundExpression::Kind;

bool same_expression(const GroundExpression& a, const GroundExpression& b) {
  if (a.kind != b.kind || a.value != b.value || a.variable != b.variable || a.operands.size() != b.operands.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.operands.size(); ++i) {
    if (!same_expression(a.operands[i], b.operands[i])) return false;
  }
  return true;
}

// Constants and arithmetic on them; `duration` says whether ?duration may
// appear (it is one value over a run, not one value over all runs).
bool reads_nothing(const GroundExpression& e, bool duration) {
  if (e.kind == Kind::Variable || e.kind == Kind::TotalTime || e.kind == Kind::Undefined) return false;
  if (e.kind == Kind::Duration && !duration) return false;
  for (const GroundExpression& o : e.operands) {
    if (!reads_nothing(o, duration)) return false;
  }
  return true;
}

// The value of an expression that reads nothing, by the evaluator the
// search uses; nothing when it reads something or cannot be evaluated (a
// division by zero).
std::optional<double> constant(const GroundExpression& e) {
  if (!reads_nothing(e, false)) return std::nullopt;
  try {
    return evaluate(e, SearchState(), EvaluationContext{});
  } catch (const EvaluationError&) {
    return std::nullopt;
  }
}

// The variables of a variable or a sum of variables; false for anything else.
bool summed_variables(const GroundExpression& e, std::vector<NumericVarId>& out) {
  if (e.kind == Kind::Variable) {
    out.push_back(e.variable);
    return true;
  }
  if (e.kind != Kind::Add) return false;
  for (const GroundExpression& o : e.operands) {
    if (!summed_variables(o, out)) return false;
  }
  return true;
}

}  // namespace

bool give_back(const GroundAction& g, const NumericAssignment& end) {
  using pddl::AssignOperator;
  if (end.assign != AssignOperator::Increase && end.assign != AssignOperator::Decrease) return false;
  if (!reads_nothing(end.value, true)) return false;
  const AssignOperator opposite =
      end.assign == AssignOperator::Increase ? AssignOperator::Decrease : AssignOperator::Increase;
  for (const ContinuousEffect& c : g.continuous) {
    if (c.variable == end.variable) return false;
  }
  for (const NumericAssignment& s : g.start.numeric) {
    if (s.variable == end.variable && s.assign == opposite && same_expression(s.value, end.value)) return true;
  }
  return false;
}

std::optional<NumericDemand> numeric_demand(const GroundComparison& c, const SearchState& state) {
  using pddl::Comparison;
  if (c.comparison == Comparison::Equal) return std::nullopt;
  NumericDemand demand;
  if (!summed_variables(c.left, demand.variables)) return std::nullopt;
  const std::optional<double> bound = constant(c.right);
  if (!bound) return std::nullopt;
  double now = 0.0;
  for (NumericVarId v : demand.variables) now += state.value(v);
  if (std::isnan(now)) return std::nullopt;
  demand.upward = c.comparison == Comparison::Greater || c.comparison == Comparison::GreaterEqual;
  demand.gap = demand.upward ? *bound - now : now - *bound;
  const bool strict = c.comparison == Comparison::Greater || c.comparison == Comparison::Less;
  if (demand.gap < 0.0 || (demand.gap == 0.0 && !strict)) return std::nullopt;
  // A strict bound met with equality still needs one application.
  if (demand.gap == 0.0) demand.gap = std::numeric_limits<double>::min();
  return demand;
}

std::optional<double> constant_step(const std::vector<const NumericAssignment*>& start,
                                    const std::vector<const NumericAssignment*>& end, NumericVarId v, bool upward) {
  using pddl::AssignOperator;
  double step = 0.0;
  for (const auto* effects : {&start, &end}) {
    for (const NumericAssignment* a : *effects) {
      if (a->variable != v) continue;
      if (a->assign != AssignOperator::Increase && a->assign != AssignOperator::Decrease) return std::nullopt;
      const std::optional<double> amount = constant(a->value);
      if (!amount) return std::nullopt;
      step += a->assign == AssignOperator::Increase ? *amount : -*amount;
    }
  }
  if (!upward) step = -step;
  if (step <= 0.0) return std::nullopt;
  return step;
}

}  // namespace alplan
