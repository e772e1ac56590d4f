// Conditions to negation normal form, durative conditions split by time,
// effects flattened into primitive effects.
#include <algorithm>
#include <optional>
#include <stdexcept>

#include "planner/normalize_internal.h"
#include "pddl_parser/writer.h"

namespace alplan::detail {

using pddl::Comparison;
using CKind = pddl::Condition::Kind;

std::uint32_t VariableScope::bind(const std::string& name) {
  bound_.emplace_back(name, next_slot_);
  return next_slot_++;
}

std::uint32_t VariableScope::slot_of(const std::string& name) const {
  for (auto it = bound_.rbegin(); it != bound_.rend(); ++it) {
    if (it->first == name) return it->second;
  }
  throw std::logic_error("unbound variable " + name + " reached normalisation");
}

LiftedCondition make_and(std::vector<LiftedCondition> children) {
  LiftedCondition result;
  result.kind = LiftedCondition::Kind::And;
  for (LiftedCondition& c : children) {
    if (c.kind == LiftedCondition::Kind::True) continue;
    if (c.kind == LiftedCondition::Kind::False) return c;
    if (c.kind == LiftedCondition::Kind::And) {
      for (LiftedCondition& grandchild : c.children) result.children.push_back(std::move(grandchild));
    } else {
      result.children.push_back(std::move(c));
    }
  }
  if (result.children.empty()) return LiftedCondition{};
  if (result.children.size() == 1) return std::move(result.children.front());
  return result;
}

LiftedCondition make_or(std::vector<LiftedCondition> children) {
  LiftedCondition result;
  result.kind = LiftedCondition::Kind::Or;
  for (LiftedCondition& c : children) {
    if (c.kind == LiftedCondition::Kind::False) continue;
    if (c.kind == LiftedCondition::Kind::True) return c;
    if (c.kind == LiftedCondition::Kind::Or) {
      for (LiftedCondition& grandchild : c.children) result.children.push_back(std::move(grandchild));
    } else {
      result.children.push_back(std::move(c));
    }
  }
  if (result.children.empty()) {
    result.kind = LiftedCondition::Kind::False;
    return result;
  }
  if (result.children.size() == 1) return std::move(result.children.front());
  return result;
}

namespace {

Comparison negate(Comparison c) {
  switch (c) {
    case Comparison::Less: return Comparison::GreaterEqual;
    case Comparison::LessEqual: return Comparison::Greater;
    case Comparison::GreaterEqual: return Comparison::Less;
    case Comparison::Greater: return Comparison::LessEqual;
    case Comparison::Equal: return Comparison::Equal;  // handled by the caller
  }
  return c;
}

bool has_timed(const pddl::Condition& c) {
  if (c.kind == CKind::Timed) return true;
  for (const pddl::Condition& child : c.children) {
    if (has_timed(child)) return true;
  }
  return false;
}

LiftedCondition quantified(LiftedCondition::Kind kind, std::vector<QuantifiedVariable> variables,
                           LiftedCondition body) {
  if (body.kind == LiftedCondition::Kind::True || body.kind == LiftedCondition::Kind::False) return body;
  LiftedCondition q;
  q.kind = kind;
  q.variables = std::move(variables);
  q.children.push_back(std::move(body));
  return q;
}

}  // namespace

std::string FormulaConverter::where(pddl::SourceLocation location) const {
  return file_ + ":" + std::to_string(location.line) + ":" + std::to_string(location.column);
}

void FormulaConverter::unsupported(pddl::SourceLocation location, const std::string& what) {
  unsupported_.push_back(where(location) + ": " + what);
}

void FormulaConverter::pddl3_use(pddl::SourceLocation location, const std::string& what) {
  task_.pddl3.uses.push_back(where(location) + ": " + what);
}

std::uint32_t FormulaConverter::preference_id(const std::string& name) {
  auto [it, inserted] = names_.preferences.emplace(name, static_cast<std::uint32_t>(task_.pddl3.preferences.size()));
  if (inserted) task_.pddl3.preferences.push_back(name);
  return it->second;
}

// A preference in a goal or condition: VAL evaluates it where the condition
// is evaluated and counts each failing instance.
void FormulaConverter::preference(const pddl::Condition& c, VariableScope& scope, bool negated) {
  const std::string name = c.preference_name.empty() ? "anonymous" : c.preference_name;
  pddl3_use(c.location, "PDDL 3 preference " + name);
  if (negated || disjunctive_depth_ > 0) {
    unsupported(c.location, "a PDDL 3 preference under a negation, disjunction or existential quantifier");
    return;
  }
  const pddl::Condition* body = &c.children.front();
  PreferenceCondition p;
  p.time = current_time_;
  if (body->kind == CKind::Timed) {
    p.time = body->time;
    body = &body->children.front();
  }
  p.preference = preference_id(name);
  p.forall = enclosing_;
  p.where = where(c.location);
  std::vector<PreferenceCondition> outer = std::move(preferences_);
  preferences_.clear();
  p.condition = condition(*body, scope);
  if (!preferences_.empty()) unsupported(c.location, "a PDDL 3 preference inside a preference");
  preferences_ = std::move(outer);
  preferences_.push_back(std::move(p));
}

TypeId FormulaConverter::type_of(const pddl::TypeNames& types) {
  if (types.empty()) return 0;
  std::string key = pddl::write_type(types);
  auto it = names_.types.find(key);
  if (it != names_.types.end()) return it->second;
  // A union type for (either a b ...) used in a signature.
  TypeInfo info;
  info.name = key;
  std::vector<bool> member(task_.objects.size(), false);
  for (const std::string& t : types) {
    for (ObjectId o : task_.types.at(names_.types.at(t)).objects) member[o] = true;
  }
  for (ObjectId o = 0; o < member.size(); ++o) {
    if (member[o]) info.objects.push_back(o);
  }
  const auto id = static_cast<TypeId>(task_.types.size());
  task_.types.push_back(std::move(info));
  names_.types.emplace(std::move(key), id);
  return id;
}

std::vector<QuantifiedVariable> FormulaConverter::bind_all(const std::vector<pddl::TypedName>& variables,
                                                           VariableScope& scope) {
  std::vector<QuantifiedVariable> result;
  for (const pddl::TypedName& v : variables) {
    const TypeId type = type_of(v.types);
    result.push_back({scope.bind(v.name), type, v.name});
  }
  return result;
}

LiftedTerm FormulaConverter::term(const pddl::Term& t, const VariableScope& scope) {
  if (t.is_variable()) return {true, scope.slot_of(t.name)};
  return {false, names_.objects.at(t.name)};
}

LiftedAtom FormulaConverter::atom(const pddl::Atom& a, const VariableScope& scope) {
  LiftedAtom result;
  result.predicate = names_.predicates.at(a.name);
  for (const pddl::Term& t : a.args) result.args.push_back(term(t, scope));
  return result;
}

LiftedExpression FormulaConverter::expression(const pddl::NumericExpression& e, const VariableScope& scope) {
  using K = pddl::NumericExpression::Kind;
  LiftedExpression result;
  switch (e.kind) {
    case K::Number: result.kind = LiftedExpression::Kind::Constant; result.value = e.value; return result;
    case K::Function:
      result.kind = LiftedExpression::Kind::Function;
      result.term.function = names_.functions.at(e.function.name);
      for (const pddl::Term& t : e.function.args) result.term.args.push_back(term(t, scope));
      return result;
    case K::Add: result.kind = LiftedExpression::Kind::Add; break;
    case K::Subtract: result.kind = LiftedExpression::Kind::Subtract; break;
    case K::Multiply: result.kind = LiftedExpression::Kind::Multiply; break;
    case K::Divide: result.kind = LiftedExpression::Kind::Divide; break;
    case K::Negate: result.kind = LiftedExpression::Kind::Negate; break;
    case K::Duration: result.kind = LiftedExpression::Kind::Duration; return result;
    case K::TotalTime: result.kind = LiftedExpression::Kind::TotalTime; return result;
    case K::ContinuousTime:
      unsupported(e.location, "#t outside the form (* #t rate) of a continuous effect (non-linear change) is not supported");
      return result;
    case K::IsViolated:
      pddl3_use(e.location, "PDDL 3 (is-violated " + e.function.name + ")");
      result.kind = LiftedExpression::Kind::IsViolated;
      result.preference = preference_id(e.function.name);
      return result;
  }
  for (const pddl::NumericExpression& operand : e.operands) result.operands.push_back(expression(operand, scope));
  return result;
}

LiftedCondition FormulaConverter::condition(const pddl::Condition& c, VariableScope& scope, bool negated) {
  LiftedCondition result;
  switch (c.kind) {
    case CKind::And:
    case CKind::Or: {
      const bool conjunction = (c.kind == CKind::And) != negated;
      std::vector<LiftedCondition> children;
      disjunctive_depth_ += conjunction ? 0 : 1;
      for (const pddl::Condition& child : c.children) children.push_back(condition(child, scope, negated));
      disjunctive_depth_ -= conjunction ? 0 : 1;
      return conjunction ? make_and(std::move(children)) : make_or(std::move(children));
    }
    case CKind::Not: return condition(c.children.front(), scope, !negated);
    case CKind::Imply: {
      std::vector<LiftedCondition> children;
      ++disjunctive_depth_;
      children.push_back(condition(c.children[0], scope, !negated));
      children.push_back(condition(c.children[1], scope, negated));
      --disjunctive_depth_;
      return negated ? make_and(std::move(children)) : make_or(std::move(children));
    }
    case CKind::Exists:
    case CKind::Forall: {
      const bool universal = (c.kind == CKind::Forall) != negated;
      std::vector<QuantifiedVariable> variables = bind_all(c.variables, scope);
      // A preference under a universal quantifier counts per instance.
      if (universal) enclosing_.insert(enclosing_.end(), variables.begin(), variables.end());
      disjunctive_depth_ += universal ? 0 : 1;
      LiftedCondition body = condition(c.children.front(), scope, negated);
      disjunctive_depth_ -= universal ? 0 : 1;
      if (universal) enclosing_.resize(enclosing_.size() - variables.size());
      scope.unbind(c.variables.size());
      return quantified(universal ? LiftedCondition::Kind::Forall : LiftedCondition::Kind::Exists,
                        std::move(variables), std::move(body));
    }
    case CKind::Atom:
      result.kind = LiftedCondition::Kind::Atom;
      result.positive = !negated;
      result.atom = atom(c.atom, scope);
      return result;
    case CKind::Equality:
      result.kind = LiftedCondition::Kind::Equality;
      result.positive = !negated;
      result.left = term(c.atom.args[0], scope);
      result.right = term(c.atom.args[1], scope);
      return result;
    case CKind::Comparison: {
      result.kind = LiftedCondition::Kind::Comparison;
      result.sides = {expression(c.expressions[0], scope), expression(c.expressions[1], scope)};
      if (negated && c.comparison == Comparison::Equal) {  // not (= a b): a < b or a > b
        LiftedCondition less = result;
        less.comparison = Comparison::Less;
        result.comparison = Comparison::Greater;
        return make_or({std::move(less), std::move(result)});
      }
      result.comparison = negated ? negate(c.comparison) : c.comparison;
      return result;
    }
    case CKind::Timed:
      unsupported(c.location, "a timed condition nested where it cannot be split by time");
      return result;
    case CKind::Preference:
      // Held true in the hard condition; evaluated apart (PreferenceCondition).
      preference(c, scope, negated);
      return LiftedCondition{};
    default:
      unsupported(c.location, "PDDL 3 trajectory constraints are not supported");
      return result;
  }
}

LiftedCondition FormulaConverter::timed_part(const pddl::Condition& c, pddl::TimeSpecifier time,
                                             VariableScope& scope) {
  switch (c.kind) {
    case CKind::Timed: {
      if (c.time != time) return LiftedCondition{};
      current_time_ = time;
      LiftedCondition part = condition(c.children.front(), scope);
      current_time_ = pddl::TimeSpecifier::AtStart;
      return part;
    }
    case CKind::Preference: {
      // (preference p (at start C)); an untimed one is read as over all.
      const pddl::Condition& inner = c.children.front();
      const pddl::TimeSpecifier at = inner.kind == CKind::Timed ? inner.time : pddl::TimeSpecifier::OverAll;
      if (at == time) {
        current_time_ = time;
        preference(c, scope, false);
        current_time_ = pddl::TimeSpecifier::AtStart;
      }
      return LiftedCondition{};
    }
    case CKind::And: {
      std::vector<LiftedCondition> children;
      for (const pddl::Condition& child : c.children) children.push_back(timed_part(child, time, scope));
      return make_and(std::move(children));
    }
    case CKind::Forall: {
      std::vector<QuantifiedVariable> variables = bind_all(c.variables, scope);
      enclosing_.insert(enclosing_.end(), variables.begin(), variables.end());
      LiftedCondition body = timed_part(c.children.front(), time, scope);
      enclosing_.resize(enclosing_.size() - variables.size());
      scope.unbind(c.variables.size());
      return quantified(LiftedCondition::Kind::Forall, std::move(variables), std::move(body));
    }
    default:
      if (has_timed(c)) {
        unsupported(c.location, "timed conditions inside (" + pddl::write_condition(c).substr(1, 6) +
                                    "...) cannot be split by time");
      }
      // The checker rejects untimed conditions of durative actions; treat
      // what remains as an invariant so nothing is silently dropped.
      return time == pddl::TimeSpecifier::OverAll ? condition(c, scope) : LiftedCondition{};
  }
}

struct FormulaConverter::EffectContext {
  bool durative = false;
  bool timed = false;
  Moment moment = Moment::Start;
  std::vector<QuantifiedVariable> forall;
  std::vector<LiftedCondition> conditions;
  bool condition_timed = false;
  Moment condition_moment = Moment::Start;
};

void FormulaConverter::effects(const pddl::Effect& e, bool durative, VariableScope& scope, ActionSchema& schema) {
  EffectContext context;
  context.durative = durative;
  effect(e, context, scope, schema);
}

void FormulaConverter::effect(const pddl::Effect& e, EffectContext& context, VariableScope& scope,
                              ActionSchema& schema) {
  using EKind = pddl::Effect::Kind;
  switch (e.kind) {
    case EKind::And:
      for (const pddl::Effect& child : e.children) effect(child, context, scope, schema);
      return;
    case EKind::Forall: {
      std::vector<QuantifiedVariable> variables = bind_all(e.variables, scope);
      context.forall.insert(context.forall.end(), variables.begin(), variables.end());
      effect(e.children.front(), context, scope, schema);
      context.forall.resize(context.forall.size() - variables.size());
      scope.unbind(e.variables.size());
      return;
    }
    case EKind::When: {
      EffectContext inner = context;
      if (context.durative && has_timed(*e.condition)) {
        LiftedCondition at_start = timed_part(*e.condition, pddl::TimeSpecifier::AtStart, scope);
        LiftedCondition at_end = timed_part(*e.condition, pddl::TimeSpecifier::AtEnd, scope);
        if (at_start.kind != LiftedCondition::Kind::True && at_end.kind != LiftedCondition::Kind::True) {
          unsupported(e.location, "a conditional effect with conditions at both start and end");
        }
        inner.condition_timed = true;
        inner.condition_moment = at_end.kind != LiftedCondition::Kind::True ? Moment::End : Moment::Start;
        inner.conditions.push_back(inner.condition_moment == Moment::End ? std::move(at_end) : std::move(at_start));
      } else {
        inner.conditions.push_back(condition(*e.condition, scope));
      }
      effect(e.children.front(), inner, scope, schema);
      return;
    }
    case EKind::Timed: {
      EffectContext inner = context;
      inner.timed = true;
      inner.moment = e.time == pddl::TimeSpecifier::AtEnd ? Moment::End : Moment::Start;
      effect(e.children.front(), inner, scope, schema);
      return;
    }
    case EKind::Add:
    case EKind::Delete:
    case EKind::Numeric: {
      PrimitiveEffect p;
      p.moment = context.moment;
      p.forall = context.forall;
      p.condition = make_and(context.conditions);
      p.condition_moment = context.condition_timed ? context.condition_moment : context.moment;
      if (e.kind == EKind::Numeric && context.durative && !context.timed) {
        if (continuous(e, context, scope, p)) schema.effects.push_back(std::move(p));
        return;
      }
      if (e.kind == EKind::Numeric) {
        p.kind = PrimitiveEffect::Kind::Numeric;
        p.target.function = names_.functions.at(e.atom.name);
        for (const pddl::Term& t : e.atom.args) p.target.args.push_back(term(t, scope));
        p.assign = e.assign;
        p.value = expression(*e.value, scope);
      } else {
        p.kind = e.kind == EKind::Add ? PrimitiveEffect::Kind::Add : PrimitiveEffect::Kind::Delete;
        p.atom = atom(e.atom, scope);
      }
      if (context.durative && !context.timed) {
        unsupported(e.location, "an untimed effect in a durative action");
      }
      schema.effects.push_back(std::move(p));
      return;
    }
  }
}

namespace {

bool mentions(const pddl::NumericExpression& e, pddl::NumericExpression::Kind kind) {
  if (e.kind == kind) return true;
  return std::any_of(e.operands.begin(), e.operands.end(), [&](const auto& o) { return mentions(o, kind); });
}

}  // namespace

// COLIN's linear continuous change (Coles et al., JAIR 2012): the value
// moves by rate x elapsed time while the action runs, the rate fixed when
// it starts. So #t must be a factor of the whole right-hand side.
bool FormulaConverter::continuous(const pddl::Effect& e, const EffectContext& context, const VariableScope& scope,
                                  PrimitiveEffect& p) {
  using K = pddl::NumericExpression::Kind;
  const pddl::NumericExpression& value = *e.value;
  if (!mentions(value, K::ContinuousTime)) {
    unsupported(e.location, "an untimed effect in a durative action");
    return false;
  }
  if (e.assign != pddl::AssignOperator::Increase && e.assign != pddl::AssignOperator::Decrease) {
    unsupported(e.location, "continuous change by " + std::string(pddl::to_string(e.assign)) +
                                " (only increase and decrease by (* #t rate) are supported)");
    return false;
  }
  if (!context.conditions.empty()) {
    unsupported(e.location, "a conditional continuous effect");
    return false;
  }
  std::optional<pddl::NumericExpression> rate;
  if (value.kind == K::ContinuousTime) {
    rate = pddl::NumericExpression{};
    rate->kind = K::Number;
    rate->value = 1.0;
  } else if (value.kind == K::Multiply && value.operands.size() == 2) {
    for (int side = 0; side < 2; ++side) {
      if (value.operands[side].kind == K::ContinuousTime && !mentions(value.operands[1 - side], K::ContinuousTime)) {
        rate = value.operands[1 - side];
      }
    }
  }
  if (!rate) {
    unsupported(value.location, "continuous change that is not (* #t rate) (non-linear in #t)");
    return false;
  }
  if (mentions(*rate, K::Duration)) {
    unsupported(value.location, "a continuous rate that depends on ?duration");
    return false;
  }
  p.kind = PrimitiveEffect::Kind::Continuous;
  p.target.function = names_.functions.at(e.atom.name);
  for (const pddl::Term& t : e.atom.args) p.target.args.push_back(term(t, scope));
  p.assign = e.assign;
  p.value = expression(*rate, scope);
  return true;
}

}  // namespace alplan::detail
