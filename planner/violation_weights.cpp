#include "planner/violation_weights.h"

#include <algorithm>

namespace alplan {

namespace {

bool reads_violations(const GroundExpression& e) {
  if (e.kind == GroundExpression::Kind::IsViolated) return true;
  return std::any_of(e.operands.begin(), e.operands.end(), reads_violations);
}

}  // namespace

std::optional<std::vector<double>> violation_coefficients(const GroundExpression& e, std::size_t preferences) {
  using K = GroundExpression::Kind;
  std::vector<double> zero(preferences, 0.0);
  if (!reads_violations(e)) return zero;
  auto scaled = [](std::vector<double> v, double by) {
    for (double& x : v) x *= by;
    return v;
  };
  switch (e.kind) {
    case K::IsViolated:
      if (e.variable < preferences) zero[e.variable] = 1.0;
      return zero;
    case K::Add:
    case K::Subtract: {
      for (std::size_t i = 0; i < e.operands.size(); ++i) {
        const std::optional<std::vector<double>> part = violation_coefficients(e.operands[i], preferences);
        if (!part) return std::nullopt;
        const double sign = e.kind == K::Subtract && (i > 0 || e.operands.size() == 1) ? -1.0 : 1.0;
        for (std::size_t p = 0; p < preferences; ++p) zero[p] += sign * (*part)[p];
      }
      return zero;
    }
    case K::Negate: {
      if (e.operands.size() != 1) return std::nullopt;
      const std::optional<std::vector<double>> part = violation_coefficients(e.operands[0], preferences);
      if (!part) return std::nullopt;
      return scaled(*part, -1.0);
    }
    case K::Multiply:
    case K::Divide: {
      // One operand reads violations; the others are constants.
      double factor = 1.0;
      std::optional<std::vector<double>> part;
      for (std::size_t i = 0; i < e.operands.size(); ++i) {
        const GroundExpression& o = e.operands[i];
        if (reads_violations(o)) {
          if (part || (e.kind == K::Divide && i > 0)) return std::nullopt;
          part = violation_coefficients(o, preferences);
          if (!part) return std::nullopt;
        } else if (o.kind == K::Constant) {
          if (e.kind == K::Divide && i > 0) {
            if (o.value == 0.0) return std::nullopt;
            factor /= o.value;
          } else {
            factor *= o.value;
          }
        } else {
          return std::nullopt;
        }
      }
      return scaled(*part, factor);
    }
    default: return std::nullopt;
  }
}

bool compiled_metric_is_lower_bound(const GroundTask& task) {
  if (!task.metric || !task.metric->minimize) return false;
  const std::optional<std::vector<double>> weights =
      violation_coefficients(task.metric->expression, task.lifted->pddl3.preferences.size());
  return weights && std::all_of(weights->begin(), weights->end(), [](double w) { return w >= 0.0; });
}

}  // namespace alplan
