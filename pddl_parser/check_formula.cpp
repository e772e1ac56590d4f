#include <algorithm>

#include "pddl_parser/check_context.h"
#include "pddl_parser/writer.h"

namespace alplan::pddl::detail {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string plural(std::size_t n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

bool is_continuous(const NumericExpression& e) {
  if (e.kind == NumericExpression::Kind::ContinuousTime) return true;
  return std::any_of(e.operands.begin(), e.operands.end(), is_continuous);
}

bool durative(Place place) { return place == Place::DurativeCondition || place == Place::DurativeEffect; }

}  // namespace

std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(2, name.size() / 3) + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(name, c);
    if (d < best_distance || (d == best_distance && !best.empty() && c < best)) {
      if (d < best_distance) best_distance = d;
      best = c;
    }
  }
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

void FormulaChecker::set_scope(const std::vector<TypedName>& parameters, std::string owner) {
  scope_.clear();
  owner_ = std::move(owner);
  push(parameters);
}

void FormulaChecker::push(const std::vector<TypedName>& variables) {
  for (const TypedName& v : variables) {
    for (const std::string& type : v.types) {
      if (!declarations_.types.is_known(type)) {
        sink_.error(v.location, "undefined type '" + type + "' of " + v.name +
                                    did_you_mean(type, declarations_.types.types()));
      }
    }
    scope_.push_back({v.name, v.types});
  }
}

const FormulaChecker::Variable* FormulaChecker::find_variable(const std::string& name) const {
  for (auto it = scope_.rbegin(); it != scope_.rend(); ++it) {
    if (it->name == name) return &*it;
  }
  return nullptr;
}

void FormulaChecker::term(const Term& t, const TypeNames& allowed, const Atom& atom, std::size_t index,
                          const char* what) {
  const std::string position = "argument " + std::to_string(index + 1) + " of " + write_atom(atom);
  if (t.is_variable()) {
    const Variable* v = find_variable(t.name);
    if (v == nullptr) {
      sink_.error(t.location, "undefined variable " + t.name + " in " + position + ": it is not a parameter" +
                                  (owner_.empty() ? "" : " of " + owner_) + " nor a quantified variable");
      return;
    }
    if (!declarations_.types.overlaps(v->types, allowed)) {
      sink_.error(t.location, "wrong argument type: " + position + " is " + t.name + " of type " +
                                  write_type(v->types.empty() ? TypeNames{"object"} : v->types) + ", but " +
                                  what + " '" + atom.name + "' expects " + write_type(allowed));
    }
    return;
  }
  auto it = declarations_.objects.find(t.name);
  if (it == declarations_.objects.end()) {
    const char* kind = declarations_.in_problem ? "object" : "constant";
    sink_.error(t.location, std::string("undefined ") + kind + " '" + t.name + "' in " + position +
                                did_you_mean(t.name, keys_of(declarations_.objects)));
    return;
  }
  // An object declared with several types belongs to each of them.
  const TypeNames& types = it->second;
  const bool fits = types.empty() ? allowed.empty() || std::find(allowed.begin(), allowed.end(), "object") !=
                                                           allowed.end()
                                  : std::any_of(types.begin(), types.end(), [&](const std::string& type) {
                                      return declarations_.types.fits(type, allowed);
                                    });
  if (!fits) {
    sink_.error(t.location, "wrong argument type: " + position + " is '" + t.name + "' of type " +
                                write_type(types.empty() ? TypeNames{"object"} : types) + ", but " + what +
                                " '" + atom.name + "' expects " + write_type(allowed));
  }
}

void FormulaChecker::atom_against(const Atom& atom, const std::vector<TypedName>& parameters,
                                  const char* what) {
  if (atom.args.size() != parameters.size()) {
    sink_.error(atom.location, std::string("wrong arity: ") + what + " '" + atom.name + "' takes " +
                                   plural(parameters.size(), "argument") + ", found " +
                                   std::to_string(atom.args.size()) + " in " + write_atom(atom));
    return;
  }
  for (std::size_t i = 0; i < atom.args.size(); ++i) term(atom.args[i], parameters[i].types, atom, i, what);
}

void FormulaChecker::check_ground_atom(const Atom& atom, const char* what) {
  auto it = declarations_.predicates.find(atom.name);
  if (it == declarations_.predicates.end()) {
    sink_.error(atom.location, "undefined predicate '" + atom.name + "' in " + what +
                                   did_you_mean(atom.name, keys_of(declarations_.predicates)));
    return;
  }
  atom_against(atom, it->second->parameters, "predicate");
}

void FormulaChecker::check_ground_function(const FunctionTerm& function) {
  auto it = declarations_.functions.find(function.name);
  if (it == declarations_.functions.end()) {
    sink_.error(function.location, "undefined function '" + function.name + "'" +
                                       did_you_mean(function.name, keys_of(declarations_.functions)));
    return;
  }
  atom_against(function, it->second->parameters, "function");
}

void FormulaChecker::check_condition(const Condition& c, Place place) { condition(c, place, false); }

void FormulaChecker::condition(const Condition& c, Place place, bool timed) {
  using Kind = Condition::Kind;
  auto untimed_literal = [&] {
    if (place == Place::DurativeCondition && !timed) {
      sink_.error(c.location, "the condition " + write_condition(c) + " of " + owner_ +
                                  " needs a time: write (at start ...), (at end ...) or (over all ...)");
    }
  };
  switch (c.kind) {
    case Kind::Atom:
      untimed_literal();
      check_ground_atom(c.atom, "a condition");
      return;
    case Kind::Equality:
      untimed_literal();
      for (std::size_t i = 0; i < c.atom.args.size(); ++i) term(c.atom.args[i], {}, c.atom, i, "equality");
      return;
    case Kind::Comparison:
      untimed_literal();
      for (const NumericExpression& e : c.expressions) check_expression(e, place);
      return;
    case Kind::Timed: {
      const bool allowed = place == Place::DurativeCondition ||
                           (place == Place::Constraint && c.time == TimeSpecifier::AtEnd);
      if (!allowed || timed) {
        sink_.error(c.location, std::string("(") + to_string(c.time) + " ...) is not allowed here: " +
                                    (timed ? "it is already inside a timed condition"
                                           : "timed conditions belong in the :condition of a durative action"));
      }
      condition(c.children.front(), place, true);
      return;
    }
    case Kind::Exists:
    case Kind::Forall:
      push(c.variables);
      condition(c.children.front(), place, timed);
      pop(c.variables.size());
      return;
    case Kind::Preference:
      if (place == Place::DerivedBody || place == Place::DurativeCondition) {
        sink_.warning(c.location, "a preference in " + owner_ + " is parsed but not used by the planner");
      }
      for (const Condition& child : c.children) condition(child, place, timed);
      return;
    case Kind::And:
    case Kind::Or:
    case Kind::Not:
    case Kind::Imply:
      for (const Condition& child : c.children) condition(child, place, timed);
      return;
    default:  // PDDL 3 modal operators
      if (place != Place::Constraint) {
        sink_.error(c.location, "the trajectory constraint " + write_condition(c) +
                                    " is allowed only in :constraints");
      }
      for (const Condition& child : c.children) condition(child, Place::Goal, timed);
      return;
  }
}

void FormulaChecker::check_effect(const Effect& e, Place place) { effect(e, place, false); }

void FormulaChecker::effect(const Effect& e, Place place, bool timed) {
  using Kind = Effect::Kind;
  auto untimed = [&] {
    if (place == Place::DurativeEffect && !timed) {
      sink_.error(e.location, "the effect " + write_effect(e) + " of " + owner_ +
                                  " needs a time: write (at start ...) or (at end ...)");
    }
  };
  switch (e.kind) {
    case Kind::And:
      for (const Effect& child : e.children) effect(child, place, timed);
      return;
    case Kind::Forall:
      push(e.variables);
      effect(e.children.front(), place, timed);
      pop(e.variables.size());
      return;
    case Kind::When:
      condition(*e.condition, place == Place::DurativeEffect ? Place::DurativeCondition : Place::Precondition,
                timed);
      effect(e.children.front(), place, timed);
      return;
    case Kind::Timed:
      if (place != Place::DurativeEffect || timed) {
        sink_.error(e.location, std::string("(") + to_string(e.time) + " ...) is not allowed here: " +
                                    (timed ? "it is already inside a timed effect"
                                           : "timed effects belong in the :effect of a durative action"));
      }
      effect(e.children.front(), place, true);
      return;
    case Kind::Add:
    case Kind::Delete:
      untimed();
      check_ground_atom(e.atom, "an effect");
      if (declarations_.derived.count(e.atom.name)) {
        sink_.error(e.location, "the effect " + write_effect(e) + " changes the derived predicate '" +
                                    e.atom.name + "', which only its :derived rule may define");
      }
      return;
    case Kind::Numeric:
      if (!is_continuous(*e.value)) untimed();
      check_ground_function(e.atom);
      check_expression(*e.value, place);
      return;
  }
}

void FormulaChecker::check_expression(const NumericExpression& e, Place place) {
  using Kind = NumericExpression::Kind;
  switch (e.kind) {
    case Kind::Function: check_ground_function(e.function); return;
    case Kind::Duration:
      if (!durative(place)) {
        sink_.error(e.location, "?duration is used outside a durative action" +
                                    (owner_.empty() ? std::string() : " (in " + owner_ + ")"));
      }
      return;
    case Kind::ContinuousTime:
      if (place != Place::DurativeEffect) {
        sink_.error(e.location, "#t is allowed only in the continuous effects of a durative action");
      }
      return;
    case Kind::TotalTime:
    case Kind::IsViolated:
      if (place != Place::Metric) {
        sink_.error(e.location, write_expression(e) + " is allowed only in :metric");
      }
      return;
    default:
      for (const NumericExpression& operand : e.operands) check_expression(operand, place);
      return;
  }
}

}  // namespace alplan::pddl::detail
