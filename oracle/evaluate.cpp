#include "oracle/evaluate.h"

#include <cmath>
#include <cstdio>

namespace alplan::oracle {
namespace {

using CKind = pddl::Condition::Kind;
using NKind = pddl::NumericExpression::Kind;

std::string object_of(const pddl::Term& term, const Binding& binding) {
  return term.is_variable() ? binding[term.name] : term.name;
}

// Every binding of `variables` to objects of their types, in turn; `body`
// returns true to stop. Returns true when it was stopped.
template <typename Body>
bool each_binding(const std::vector<pddl::TypedName>& variables, std::size_t k, Scope& scope, Body&& body) {
  if (k == variables.size()) return body();
  // A copy: objects_of may grow the World's cache while we iterate.
  const std::vector<std::string> objects = scope.world.objects_of(variables[k].types);
  for (const std::string& o : objects) {
    scope.binding.push(variables[k].name, o);
    const bool stop = each_binding(variables, k + 1, scope, body);
    scope.binding.pop();
    if (stop) return true;
  }
  return false;
}

bool reads_numbers_or_axioms(const pddl::Condition& c, const World& world) {
  if (c.kind == CKind::Comparison) return true;
  if (c.kind == CKind::Atom) return world.is_derived(c.atom.name);
  for (const pddl::Condition& child : c.children) {
    if (reads_numbers_or_axioms(child, world)) return true;
  }
  return false;
}

bool atom_holds(const pddl::Atom& atom, Scope& scope) {
  const int id = scope.world.atoms().id(ground(atom, scope.binding));
  return scope.world.is_derived(atom.name) ? scope.state.derived_holds(id) : scope.state.holds(id);
}

}  // namespace

const std::string& Binding::operator[](const std::string& variable) const {
  for (auto it = pairs_.rbegin(); it != pairs_.rend(); ++it) {
    if (it->first == variable) return it->second;
  }
  throw std::logic_error("the variable " + variable + " is not bound");
}

std::string Binding::text() const {
  std::string out;
  for (const auto& [variable, object] : pairs_) out += (out.empty() ? "" : " ") + variable + "=" + object;
  return out;
}

GroundName ground(const pddl::Atom& atom, const Binding& binding) {
  GroundName g;
  g.name = atom.name;
  g.args.reserve(atom.args.size());
  for (const pddl::Term& t : atom.args) g.args.push_back(object_of(t, binding));
  return g;
}

bool compare(pddl::Comparison op, double l, double r, const Comparisons& c) {
  switch (op) {
    case pddl::Comparison::Less: return l < r + c.slack;
    case pddl::Comparison::LessEqual: return l <= r + c.slack;
    case pddl::Comparison::Equal: return c.slack == 0.0 ? l == r : std::fabs(l - r) < c.slack;
    case pddl::Comparison::GreaterEqual: return l + c.slack >= r;
    case pddl::Comparison::Greater: return l + c.slack > r;
  }
  return false;
}

bool holds(const pddl::Condition& c, Scope& scope) {
  switch (c.kind) {
    case CKind::And:
      // Literals first, comparisons and derived atoms after, as VAL orders
      // a conjunction: it decides whether an undefined fluent is ever read.
      for (const bool later : {false, true}) {
        for (const pddl::Condition& child : c.children) {
          if (reads_numbers_or_axioms(child, scope.world) == later && !holds(child, scope)) return false;
        }
      }
      return true;
    case CKind::Or:
      for (const pddl::Condition& child : c.children) {
        if (holds(child, scope)) return true;
      }
      return false;
    case CKind::Not: return !holds(c.children.front(), scope);
    case CKind::Imply: return !holds(c.children[0], scope) || holds(c.children[1], scope);
    case CKind::Exists:
      return each_binding(c.variables, 0, scope, [&] { return holds(c.children.front(), scope); });
    case CKind::Forall:
      return !each_binding(c.variables, 0, scope, [&] { return !holds(c.children.front(), scope); });
    case CKind::Atom: return atom_holds(c.atom, scope);
    case CKind::Equality:
      return object_of(c.atom.args[0], scope.binding) == object_of(c.atom.args[1], scope.binding);
    case CKind::Comparison:
      return compare(c.comparison, value(c.expressions[0], scope), value(c.expressions[1], scope), scope.comparisons);
    case CKind::Preference: {
      if (!scope.preference_counts && !scope.preference_instances) return true;
      if (holds(c.children.front(), scope)) return true;
      const std::string name = c.preference_name.empty() ? kAnonymousPreference : c.preference_name;
      if (scope.preference_instances) {
        char node[32];
        std::snprintf(node, sizeof node, "%p", static_cast<const void*>(&c));
        (*scope.preference_instances)[std::string(node) + " " + scope.binding.text()] = name;
      } else {
        (*scope.preference_counts)[name] += 1.0;
      }
      return true;
    }
    default:
      throw std::logic_error("a timed condition or trajectory constraint where a state formula belongs");
  }
}

double value(const pddl::NumericExpression& e, Scope& scope) {
  switch (e.kind) {
    case NKind::Number: return e.value;
    case NKind::Function: {
      const GroundName g = ground(e.function, scope.binding);
      const std::optional<double> v = scope.state.value(scope.world.fluents().id(g));
      if (!v) throw UndefinedValue("the fluent " + to_string(g) + " has no value");
      return *v;
    }
    case NKind::Add: {
      double sum = 0.0;
      for (const pddl::NumericExpression& o : e.operands) sum += value(o, scope);
      return sum;
    }
    case NKind::Multiply: {
      double product = 1.0;
      for (const pddl::NumericExpression& o : e.operands) product *= value(o, scope);
      return product;
    }
    case NKind::Subtract: return value(e.operands[0], scope) - value(e.operands[1], scope);
    case NKind::Divide: {
      // Division by zero gives an infinity or NaN, as in VAL; a comparison
      // with NaN is false.
      const double numerator = value(e.operands[0], scope);
      return numerator / value(e.operands[1], scope);
    }
    case NKind::Negate: return -value(e.operands[0], scope);
    case NKind::Duration:
      if (!scope.duration) throw std::logic_error("?duration outside a durative action");
      return *scope.duration;
    case NKind::TotalTime:
      if (!scope.total_time) throw std::logic_error("(total-time) outside a metric");
      return *scope.total_time;
    case NKind::IsViolated: {
      if (!scope.violations) throw std::logic_error("(is-violated) outside a metric");
      auto it = scope.violations->find(e.function.name);
      return it == scope.violations->end() ? 0.0 : it->second;
    }
    case NKind::ContinuousTime: throw NotJudged("continuous change (#t)");
  }
  return 0.0;
}

}  // namespace alplan::oracle
