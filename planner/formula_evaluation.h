// Evaluation of ground expressions, conditions and axioms in a state. The
// state type S provides `bool fact(FactId) const`, `double value(NumericVarId)
// const` and, for axioms, `void set_fact(FactId, bool)`. The validator, the
// monitor and the planner share these definitions, so they cannot disagree on
// what a condition means.
#pragma once

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "planner/ground_task.h"

namespace alplan {

// VAL compares numeric preconditions and goals with this slack, so that `<`
// and `<=` agree on values that differ by rounding.
constexpr double kNumericSlack = 0.0001;

struct EvaluationContext {
  double duration = std::nan("");    // ?duration of the action being evaluated
  double total_time = std::nan("");  // (total-time), in metrics
  // Violations per PDDL 3 preference, for (is-violated name) in metrics.
  const std::vector<double>* violations = nullptr;
};

// Reading a numeric value the problem never defined, or dividing by zero.
class EvaluationError : public std::runtime_error {
 public:
  explicit EvaluationError(const std::string& what, NumericVarId variable = kNoId)
      : std::runtime_error(what), variable_(variable) {}
  // The variable that had no value, or kNoId.
  NumericVarId variable() const { return variable_; }

 private:
  NumericVarId variable_;
};

bool compare_values(pddl::Comparison comparison, double left, double right, double slack);

template <typename S>
double evaluate(const GroundExpression& e, const S& state, const EvaluationContext& context) {
  using K = GroundExpression::Kind;
  switch (e.kind) {
    case K::Constant: return e.value;
    case K::Variable: {
      const double v = state.value(e.variable);
      if (std::isnan(v)) throw EvaluationError("undefined numeric value", e.variable);
      return v;
    }
    case K::Duration:
      if (std::isnan(context.duration)) throw EvaluationError("?duration outside a durative action");
      return context.duration;
    case K::TotalTime: return context.total_time;
    case K::Undefined: throw EvaluationError("undefined value of " + e.undefined_term);
    case K::IsViolated:
      if (!context.violations) throw EvaluationError("(is-violated ...) outside a metric");
      return e.variable < context.violations->size() ? (*context.violations)[e.variable] : 0.0;
    case K::Negate: return -evaluate(e.operands[0], state, context);
    case K::Subtract: return evaluate(e.operands[0], state, context) - evaluate(e.operands[1], state, context);
    case K::Divide: {
      const double divisor = evaluate(e.operands[1], state, context);
      if (divisor == 0.0) throw EvaluationError("division by zero");
      return evaluate(e.operands[0], state, context) / divisor;
    }
    case K::Add:
    case K::Multiply: {
      double v = evaluate(e.operands[0], state, context);
      for (std::size_t i = 1; i < e.operands.size(); ++i) {
        const double w = evaluate(e.operands[i], state, context);
        v = e.kind == K::Add ? v + w : v * w;
      }
      return v;
    }
  }
  return 0.0;
}

template <typename S>
bool holds(const GroundComparison& c, const S& state, const EvaluationContext& context, double slack) {
  return compare_values(c.comparison, evaluate(c.left, state, context), evaluate(c.right, state, context), slack);
}

template <typename S>
bool holds(const GroundFormula& f, const S& state, const EvaluationContext& context, double slack) {
  using K = GroundFormula::Kind;
  switch (f.kind) {
    case K::True: return true;
    case K::False: return false;
    case K::Literal: return state.fact(f.fact) == f.positive;
    case K::Comparison: return holds(f.comparison, state, context, slack);
    case K::And:
      for (const GroundFormula& child : f.children) {
        if (!holds(child, state, context, slack)) return false;
      }
      return true;
    case K::Or:
      for (const GroundFormula& child : f.children) {
        if (holds(child, state, context, slack)) return true;
      }
      return false;
  }
  return false;
}

// Where a condition fails: which part, by list and index.
struct Unsatisfied {
  enum class Part : unsigned char { Never, Positive, Negative, Numeric, Complex };
  Part part = Part::Never;
  std::size_t index = 0;
};

template <typename S>
std::optional<Unsatisfied> first_unsatisfied(const ConditionSet& c, const S& state, const EvaluationContext& context,
                                             double slack) {
  using P = Unsatisfied::Part;
  if (c.never) return Unsatisfied{P::Never, 0};
  for (std::size_t i = 0; i < c.positive.size(); ++i) {
    if (!state.fact(c.positive[i])) return Unsatisfied{P::Positive, i};
  }
  for (std::size_t i = 0; i < c.negative.size(); ++i) {
    if (state.fact(c.negative[i])) return Unsatisfied{P::Negative, i};
  }
  for (std::size_t i = 0; i < c.numeric.size(); ++i) {
    if (!holds(c.numeric[i], state, context, slack)) return Unsatisfied{P::Numeric, i};
  }
  for (std::size_t i = 0; i < c.complex.size(); ++i) {
    if (!holds(c.complex[i], state, context, slack)) return Unsatisfied{P::Complex, i};
  }
  return std::nullopt;
}

template <typename S>
bool holds(const ConditionSet& c, const S& state, const EvaluationContext& context, double slack) {
  return !first_unsatisfied(c, state, context, slack);
}

// The failing part as PDDL.
std::string describe(const GroundTask& task, const ConditionSet& condition, const Unsatisfied& where);

// Derived predicates: every axiom head is reset, then each stratum is
// closed under its axioms, lowest stratum first.
template <typename S>
void derive(const GroundTask& task, S& state) {
  if (task.axioms.empty()) return;
  for (const GroundAxiom& axiom : task.axioms) state.set_fact(axiom.head, false);
  const EvaluationContext context;
  std::size_t begin = 0;
  while (begin < task.axioms.size()) {
    std::size_t end = begin;
    while (end < task.axioms.size() && task.axioms[end].stratum == task.axioms[begin].stratum) ++end;
    bool changed = true;
    while (changed) {
      changed = false;
      for (std::size_t a = begin; a < end; ++a) {
        const GroundAxiom& axiom = task.axioms[a];
        if (!state.fact(axiom.head) && holds(axiom.body, state, context, 0.0)) {
          state.set_fact(axiom.head, true);
          changed = true;
        }
      }
    }
    begin = end;
  }
}

}  // namespace alplan
