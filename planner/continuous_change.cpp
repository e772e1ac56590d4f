#include "planner/continuous_change.h"

#include <algorithm>
#include <cmath>

#include "planner/formula_evaluation.h"
#include "planner/ground_printer.h"

namespace alplan {
namespace {

using K = GroundExpression::Kind;

void add_term(LinearForm& f, NumericVarId v, double coefficient) {
  for (auto& [var, c] : f.terms) {
    if (var == v) {
      c += coefficient;
      return;
    }
  }
  f.terms.emplace_back(v, coefficient);
}

bool is_constant(const LinearForm& f) { return f.terms.empty() && f.duration == 0.0; }

LinearForm scaled(LinearForm f, double k) {
  f.constant *= k;
  f.duration *= k;
  for (auto& term : f.terms) term.second *= k;
  return f;
}

LinearForm plus(LinearForm a, const LinearForm& b) {
  a.constant += b.constant;
  a.duration += b.duration;
  for (const auto& [v, c] : b.terms) add_term(a, v, c);
  return a;
}

// Throws EvaluationError on an undefined value; nullopt when not linear.
std::optional<LinearForm> linearize(const GroundExpression& e, const ContinuousModel& model, const SearchState& state,
                                    double duration) {
  LinearForm f;
  switch (e.kind) {
    case K::Constant: f.constant = e.value; return f;
    case K::Variable:
      if (model.changing(e.variable)) {
        f.terms.emplace_back(e.variable, 1.0);
      } else {
        f.constant = evaluate(e, state, EvaluationContext{});
      }
      return f;
    case K::Duration:
      if (std::isnan(duration)) {
        f.duration = 1.0;
      } else {
        f.constant = duration;
      }
      return f;
    case K::TotalTime:
    case K::IsViolated:
    case K::Undefined: {
      EvaluationContext context;
      context.duration = duration;
      f.constant = evaluate(e, state, context);
      return f;
    }
    case K::Negate: {
      std::optional<LinearForm> inner = linearize(e.operands[0], model, state, duration);
      if (!inner) return std::nullopt;
      return scaled(*inner, -1.0);
    }
    case K::Add:
    case K::Subtract: {
      std::optional<LinearForm> acc = linearize(e.operands[0], model, state, duration);
      for (std::size_t i = 1; acc && i < e.operands.size(); ++i) {
        std::optional<LinearForm> next = linearize(e.operands[i], model, state, duration);
        if (!next) return std::nullopt;
        acc = plus(*acc, e.kind == K::Add ? *next : scaled(*next, -1.0));
      }
      return acc;
    }
    case K::Multiply: {
      std::optional<LinearForm> acc = linearize(e.operands[0], model, state, duration);
      for (std::size_t i = 1; acc && i < e.operands.size(); ++i) {
        std::optional<LinearForm> next = linearize(e.operands[i], model, state, duration);
        if (!next) return std::nullopt;
        if (is_constant(*next)) {
          acc = scaled(*acc, next->constant);
        } else if (is_constant(*acc)) {
          acc = scaled(*next, acc->constant);
        } else {
          return std::nullopt;
        }
      }
      return acc;
    }
    case K::Divide: {
      std::optional<LinearForm> num = linearize(e.operands[0], model, state, duration);
      std::optional<LinearForm> den = linearize(e.operands[1], model, state, duration);
      if (!num || !den || !is_constant(*den)) return std::nullopt;
      if (den->constant == 0.0) throw EvaluationError("division by zero");
      return scaled(*num, 1.0 / den->constant);
    }
  }
  return std::nullopt;
}

// Whether an expression is linear in the changing variables whatever the
// values of the others (?duration counts as fixed: a product with it is
// checked again when the snap is applied).
bool linear_shape(const GroundExpression& e, const ContinuousModel& model) {
  switch (e.kind) {
    case K::Multiply: {
      int changing = 0;
      for (const GroundExpression& o : e.operands) {
        if (!linear_shape(o, model)) return false;
        if (model.changing(o)) ++changing;
      }
      return changing <= 1;
    }
    case K::Divide:
      return linear_shape(e.operands[0], model) && !model.changing(e.operands[1]);
    default:
      return std::all_of(e.operands.begin(), e.operands.end(),
                         [&](const GroundExpression& o) { return linear_shape(o, model); });
  }
}

void collect(const GroundExpression& e, std::vector<NumericVarId>& out) {
  if (e.kind == K::Variable) out.push_back(e.variable);
  for (const GroundExpression& o : e.operands) collect(o, out);
}

bool mentions(const GroundExpression& e, const std::vector<bool>& changing) {
  if (e.kind == K::Variable) return changing[e.variable];
  return std::any_of(e.operands.begin(), e.operands.end(), [&](const auto& o) { return mentions(o, changing); });
}

bool mentions(const GroundFormula& f, const ContinuousModel& model) {
  if (f.kind == GroundFormula::Kind::Comparison) return model.changing(f.comparison);
  return std::any_of(f.children.begin(), f.children.end(), [&](const auto& c) { return mentions(c, model); });
}

std::optional<LinearCondition> compared(const GroundTask& task, const GroundComparison& c,
                                        const ContinuousModel& model, const SearchState& state, double duration) {
  std::optional<LinearForm> left = linearize(c.left, model, state, duration);
  std::optional<LinearForm> right = linearize(c.right, model, state, duration);
  if (!left || !right) return std::nullopt;
  return LinearCondition{plus(*left, scaled(*right, -1.0)), c.comparison, write_comparison(task, c)};
}

}  // namespace

bool ContinuousModel::changing(const GroundExpression& e) const { return mentions(e, changing_); }

std::shared_ptr<const ContinuousModel> ContinuousModel::build(const GroundTask& task) {
  const bool any = std::any_of(task.actions.begin(), task.actions.end(),
                               [](const GroundAction& a) { return !a.continuous.empty(); });
  if (!any) return nullptr;
  return std::shared_ptr<const ContinuousModel>(new ContinuousModel(task));
}

ContinuousModel::ContinuousModel(const GroundTask& task) : task_(&task), changing_(task.numeric.size(), false) {
  for (const GroundAction& a : task.actions) {
    for (const ContinuousEffect& c : a.continuous) changing_[c.variable] = true;
  }
  // A value computed from a changing one changes with time too.
  for (bool grew = true; grew;) {
    grew = false;
    for (const GroundAction& a : task.actions) {
      for (const HappeningEffects* h : {&a.start, &a.end}) {
        for (const NumericAssignment& n : h->numeric) {
          if (!changing_[n.variable] && mentions(n.value, changing_)) grew = changing_[n.variable] = true;
        }
      }
    }
  }
  check_linear(task);
  index_readers_and_writers(task);
}

void ContinuousModel::check_linear(const GroundTask& task) {
  auto refuse = [&](const GroundAction& a, const std::string& what) {
    if (!unsupported_) unsupported_ = "the action " + task.action_name(a) + " has " + what;
  };
  auto check_conditions = [&](const GroundAction& a, const ConditionSet& c) {
    for (const GroundComparison& cmp : c.numeric) {
      if (changing(cmp) && (!linear_shape(cmp.left, *this) || !linear_shape(cmp.right, *this))) {
        refuse(a, "a condition non-linear in continuously changing values: " + write_comparison(task, cmp));
      }
    }
    for (const GroundFormula& f : c.complex) {
      if (mentions(f, *this)) refuse(a, "a disjunctive condition on continuously changing values");
    }
  };
  for (const GroundAction& a : task.actions) {
    for (const ContinuousEffect& c : a.continuous) {
      if (changing(c.rate)) refuse(a, "a continuous rate that itself changes with time");
    }
    for (const ConditionSet* c : {&a.at_start, &a.over_all, &a.at_end}) check_conditions(a, *c);
    for (const GroundDurationConstraint& d : a.duration) {
      if (!linear_shape(d.value, *this)) refuse(a, "a duration constraint non-linear in continuously changing values");
    }
    for (const HappeningEffects* h : {&a.start, &a.end}) {
      for (const NumericAssignment& n : h->numeric) {
        const bool scale = n.assign == pddl::AssignOperator::ScaleUp || n.assign == pddl::AssignOperator::ScaleDown;
        if (!linear_shape(n.value, *this) || (scale && changing_[n.variable] && changing(n.value))) {
          refuse(a, "an effect non-linear in continuously changing values");
        }
      }
      for (const ConditionalEffect& c : h->conditional) {
        bool touches = std::any_of(c.condition.numeric.begin(), c.condition.numeric.end(),
                                   [&](const GroundComparison& cmp) { return changing(cmp); });
        for (const NumericAssignment& n : c.numeric) touches = touches || changing_[n.variable] || changing(n.value);
        if (touches) refuse(a, "a conditional effect on continuously changing values");
      }
    }
  }
  for (const GroundAxiom& x : task.axioms) {
    for (const GroundComparison& cmp : x.body.numeric) {
      if (changing(cmp) && !unsupported_) {
        unsupported_ = "a derived predicate reads a continuously changing value: " + write_comparison(task, cmp);
      }
    }
  }
}

void ContinuousModel::index_readers_and_writers(const GroundTask& task) {
  writers_.resize(task.numeric.size());
  for (ActionId a = 0; a < task.actions.size(); ++a) {
    std::vector<NumericVarId> written;
    for (const ContinuousEffect& c : task.actions[a].continuous) written.push_back(c.variable);
    for (const HappeningEffects* h : {&task.actions[a].start, &task.actions[a].end}) {
      for (const NumericAssignment& n : h->numeric) written.push_back(n.variable);
    }
    std::sort(written.begin(), written.end());
    written.erase(std::unique(written.begin(), written.end()), written.end());
    for (NumericVarId v : written) {
      if (changing_[v]) writers_[v].push_back(a);
    }
  }
  comparisons_.resize(task.numeric.size());
  auto index = [&](const ConditionSet& c) {
    for (const GroundComparison& cmp : c.numeric) {
      std::vector<NumericVarId> read;
      collect(cmp.left, read);
      collect(cmp.right, read);
      for (NumericVarId v : read) {
        if (changing_[v] && (comparisons_[v].empty() || comparisons_[v].back() != &cmp)) comparisons_[v].push_back(&cmp);
      }
    }
  };
  for (const GroundAction& a : task.actions) {
    for (const ConditionSet* c : {&a.at_start, &a.over_all, &a.at_end}) index(*c);
  }
  index(task.goal);
}

ContinuousModel::NeededBounds ContinuousModel::needed_bounds(NumericVarId v, const SearchState& state) const {
  NeededBounds needed;
  for (const GroundComparison* cmp : comparisons_[v]) {
    if (needed.least && needed.greatest) break;
    try {
      // ?duration at 0, the lower end of the relaxation's [0, inf).
      EvaluationContext context;
      context.duration = 0.0;
      if (holds(*cmp, state, context, 0.0)) continue;
      const std::optional<LinearCondition> l = compared(*task_, *cmp, *this, state, 0.0);
      double coefficient = 0.0;
      if (l) {
        for (const auto& [var, c] : l->form.terms) {
          if (var == v) coefficient += c;
        }
      }
      // form (op) 0: a larger form helps >=, a smaller helps <=.
      const bool larger = l && (l->comparison == pddl::Comparison::GreaterEqual ||
                                l->comparison == pddl::Comparison::Greater);
      const bool smaller = l && (l->comparison == pddl::Comparison::LessEqual || l->comparison == pddl::Comparison::Less);
      if (!l || coefficient == 0.0 || (!larger && !smaller)) {
        needed.least = needed.greatest = true;
      } else if (larger == (coefficient > 0.0)) {
        needed.greatest = true;
      } else {
        needed.least = true;
      }
    } catch (const EvaluationError&) {
      // ?duration, or an undefined value: the condition is not decided here.
      needed.least = needed.greatest = true;
    }
  }
  return needed;
}

bool ContinuousModel::holds_fixed_part(const ConditionSet& c, const SearchState& state, double duration) const {
  if (c.never) return false;
  for (FactId f : c.positive) {
    if (!state.fact(f)) return false;
  }
  for (FactId f : c.negative) {
    if (state.fact(f)) return false;
  }
  EvaluationContext context;
  context.duration = duration;
  try {
    for (const GroundComparison& cmp : c.numeric) {
      if (!changing(cmp) && !holds(cmp, state, context, 0.0)) return false;
    }
    for (const GroundFormula& f : c.complex) {
      if (!holds(f, state, context, 0.0)) return false;
    }
  } catch (const EvaluationError&) {
    return false;
  }
  return true;
}

std::optional<ContinuousStep> ContinuousModel::step(const GroundAction& action, SnapKind kind,
                                                    const SearchState& before, double duration) const {
  ContinuousStep out;
  const bool end = kind == SnapKind::End;
  try {
    auto conditions = [&](const ConditionSet& c, std::vector<LinearCondition>& into) {
      for (const GroundComparison& cmp : c.numeric) {
        if (!changing(cmp)) continue;
        std::optional<LinearCondition> l = compared(*task_, cmp, *this, before, duration);
        if (!l) return false;
        into.push_back(std::move(*l));
      }
      return true;
    };
    if (!conditions(end ? action.at_end : action.at_start, out.conditions)) return std::nullopt;
    if (kind == SnapKind::Start && !conditions(action.over_all, out.invariants)) return std::nullopt;
    if (action.durative) {
      const Moment moment = end ? Moment::End : Moment::Start;
      for (const GroundDurationConstraint& d : action.duration) {
        if (d.moment != moment || !changing(d.value)) continue;
        std::optional<LinearForm> value = linearize(d.value, *this, before, duration);
        if (!value) return std::nullopt;
        LinearForm form = scaled(*value, -1.0);
        form.duration += 1.0;  // ?duration - value (op) 0
        out.conditions.push_back({std::move(form), d.comparison, "(" + std::string(pddl::to_string(d.comparison)) +
                                                                    " ?duration " + write_expression(*task_, d.value) + ")"});
      }
    }
    const HappeningEffects& effects = end ? action.end : action.start;
    for (const NumericAssignment& n : effects.numeric) {
      if (!changing_[n.variable]) continue;
      std::optional<LinearForm> value = linearize(n.value, *this, before, duration);
      if (!value) return std::nullopt;
      out.effects.push_back({n.variable, n.assign, std::move(*value)});
    }
    if (kind == SnapKind::Start) out.rates = signed_rates(action, before, duration);
  } catch (const EvaluationError&) {
    return std::nullopt;
  }
  return out;
}

std::optional<std::vector<LinearCondition>> ContinuousModel::goal(const ConditionSet& goal,
                                                                   const SearchState& state) const {
  std::vector<LinearCondition> out;
  try {
    for (const GroundComparison& cmp : goal.numeric) {
      if (!changing(cmp)) continue;
      std::optional<LinearCondition> l = compared(*task_, cmp, *this, state, std::nan(""));
      if (!l) return std::nullopt;
      out.push_back(std::move(*l));
    }
  } catch (const EvaluationError&) {
    return std::nullopt;
  }
  return out;
}

}  // namespace alplan
