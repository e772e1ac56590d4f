#include "planner/linear_metric.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace alplan {
namespace {

bool increasing_only(const GroundTask& task, NumericVarId v) {
  auto check = [&](const std::vector<NumericAssignment>& list) {
    for (const NumericAssignment& a : list) {
      if (a.variable != v) continue;
      if (a.assign != pddl::AssignOperator::Increase) return false;
      if (a.value.kind != GroundExpression::Kind::Constant || a.value.value < 0) return false;
    }
    return true;
  };
  for (const GroundAction& action : task.actions) {
    // Changed with time, its value depends on the schedule.
    for (const ContinuousEffect& c : action.continuous) {
      if (c.variable == v) return false;
    }
    for (const HappeningEffects* e : {&action.start, &action.end}) {
      if (!check(e->numeric)) return false;
      for (const ConditionalEffect& c : e->conditional) {
        if (!check(c.numeric)) return false;
      }
    }
  }
  return true;
}

// Adds `scale` times the expression into the metric; false when the
// expression is not a non-negative combination of monotone terms.
bool collect(const GroundTask& task, const GroundExpression& e, double scale, LinearMetric& into,
             std::map<NumericVarId, double>& weights) {
  using K = GroundExpression::Kind;
  switch (e.kind) {
    case K::Constant: into.constant += scale * e.value; return true;
    case K::TotalTime: into.time_weight += scale; return true;
    case K::Variable:
      if (!increasing_only(task, e.variable)) return false;
      weights[e.variable] += scale;
      return true;
    case K::Add:
      return std::all_of(e.operands.begin(), e.operands.end(),
                         [&](const GroundExpression& o) { return collect(task, o, scale, into, weights); });
    case K::Multiply: {
      if (e.operands.size() != 2) return false;
      for (int c = 0; c < 2; ++c) {
        const GroundExpression& factor = e.operands[c];
        if (factor.kind == K::Constant && factor.value >= 0) {
          return collect(task, e.operands[1 - c], scale * factor.value, into, weights);
        }
      }
      return false;
    }
    default: return false;
  }
}

double cost_of(const HappeningEffects& effects, const std::map<NumericVarId, double>& weights) {
  double cost = 0.0;
  for (const NumericAssignment& a : effects.numeric) {
    const auto it = weights.find(a.variable);
    if (it != weights.end()) cost += it->second * a.value.value;  // a constant increase: checked above
  }
  return cost;
}

}  // namespace

double LinearMetric::value(const SearchState& state, double makespan) const {
  double sum = constant + time_weight * makespan;
  for (const auto& [v, w] : variables) {
    const double x = state.value(v);
    if (!std::isnan(x)) sum += w * x;
  }
  return sum;
}

double minimised(const GroundTask& task, double value) {
  return task.metric && !task.metric->minimize ? -value : value;
}

std::optional<LinearMetric> linear_metric(const GroundTask& task) {
  if (!task.metric || !task.metric->minimize) return std::nullopt;
  LinearMetric metric;
  std::map<NumericVarId, double> weights;
  if (!collect(task, task.metric->expression, 1.0, metric, weights)) return std::nullopt;
  metric.variables.assign(weights.begin(), weights.end());
  metric.start_cost.reserve(task.actions.size());
  metric.end_cost.reserve(task.actions.size());
  for (const GroundAction& action : task.actions) {
    metric.start_cost.push_back(cost_of(action.start, weights));
    metric.end_cost.push_back(action.durative ? cost_of(action.end, weights) : 0.0);
  }
  return metric;
}

}  // namespace alplan
