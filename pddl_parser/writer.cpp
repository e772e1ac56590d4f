#include "pddl_parser/writer.h"

#include <charconv>
#include <cmath>

namespace alplan::pddl {
namespace {

void put_atom(std::string& out, const Atom& atom) {
  out += '(';
  out += atom.name;
  for (const Term& t : atom.args) {
    out += ' ';
    out += t.name;
  }
  out += ')';
}

void put_typed_list(std::string& out, const std::vector<TypedName>& names) {
  bool first = true;
  for (const TypedName& n : names) {
    if (!first) out += ' ';
    first = false;
    out += n.name;
    if (!n.types.empty()) {
      out += " - ";
      out += write_type(n.types);
    }
  }
}

void put_expression(std::string& out, const NumericExpression& e) {
  using Kind = NumericExpression::Kind;
  auto operation = [&](const char* op) {
    out += '(';
    out += op;
    for (const NumericExpression& operand : e.operands) {
      out += ' ';
      put_expression(out, operand);
    }
    out += ')';
  };
  switch (e.kind) {
    case Kind::Number: out += format_number(e.value); return;
    case Kind::Function: put_atom(out, e.function); return;
    case Kind::Add: operation("+"); return;
    case Kind::Subtract: operation("-"); return;
    case Kind::Multiply: operation("*"); return;
    case Kind::Divide: operation("/"); return;
    case Kind::Negate: operation("-"); return;
    case Kind::Duration: out += "?duration"; return;
    case Kind::TotalTime: out += "(total-time)"; return;
    case Kind::ContinuousTime: out += "#t"; return;
    case Kind::IsViolated: out += "(is-violated " + e.function.name + ")"; return;
  }
}

const char* modal_name(Condition::Kind kind) {
  using Kind = Condition::Kind;
  switch (kind) {
    case Kind::Always: return "always";
    case Kind::Sometime: return "sometime";
    case Kind::Within: return "within";
    case Kind::AtMostOnce: return "at-most-once";
    case Kind::SometimeAfter: return "sometime-after";
    case Kind::SometimeBefore: return "sometime-before";
    case Kind::AlwaysWithin: return "always-within";
    case Kind::HoldDuring: return "hold-during";
    case Kind::HoldAfter: return "hold-after";
    default: return "?";
  }
}

// `indent` < 0 writes on one line; otherwise the children of a top-level
// conjunction go on their own lines at that indentation.
void put_condition(std::string& out, const Condition& c, int indent);

void put_children(std::string& out, const std::vector<Condition>& children, int indent) {
  for (const Condition& child : children) {
    if (indent >= 0) {
      out += '\n';
      out.append(static_cast<std::size_t>(indent), ' ');
    } else {
      out += ' ';
    }
    put_condition(out, child, -1);
  }
}

void put_condition(std::string& out, const Condition& c, int indent) {
  using Kind = Condition::Kind;
  switch (c.kind) {
    case Kind::And: out += "(and"; put_children(out, c.children, indent); out += ')'; return;
    case Kind::Or: out += "(or"; put_children(out, c.children, -1); out += ')'; return;
    case Kind::Not: out += "(not"; put_children(out, c.children, -1); out += ')'; return;
    case Kind::Imply: out += "(imply"; put_children(out, c.children, -1); out += ')'; return;
    case Kind::Exists:
    case Kind::Forall:
      out += c.kind == Kind::Exists ? "(exists (" : "(forall (";
      put_typed_list(out, c.variables);
      out += ')';
      put_children(out, c.children, -1);
      out += ')';
      return;
    case Kind::Atom: put_atom(out, c.atom); return;
    case Kind::Equality: put_atom(out, c.atom); return;
    case Kind::Comparison:
      out += '(';
      out += to_string(c.comparison);
      for (const NumericExpression& e : c.expressions) {
        out += ' ';
        put_expression(out, e);
      }
      out += ')';
      return;
    case Kind::Timed:
      out += '(';
      out += to_string(c.time);
      put_children(out, c.children, -1);
      out += ')';
      return;
    case Kind::Preference:
      out += "(preference";
      if (!c.preference_name.empty()) out += ' ' + c.preference_name;
      put_children(out, c.children, -1);
      out += ')';
      return;
    default:
      out += '(';
      out += modal_name(c.kind);
      for (double n : c.numbers) out += ' ' + format_number(n);
      put_children(out, c.children, -1);
      out += ')';
      return;
  }
}

void put_effect(std::string& out, const Effect& e, int indent) {
  using Kind = Effect::Kind;
  switch (e.kind) {
    case Kind::And:
      out += "(and";
      for (const Effect& child : e.children) {
        if (indent >= 0) {
          out += '\n';
          out.append(static_cast<std::size_t>(indent), ' ');
        } else {
          out += ' ';
        }
        put_effect(out, child, -1);
      }
      out += ')';
      return;
    case Kind::Forall:
      out += "(forall (";
      put_typed_list(out, e.variables);
      out += ") ";
      put_effect(out, e.children.front(), -1);
      out += ')';
      return;
    case Kind::When:
      out += "(when ";
      put_condition(out, *e.condition, -1);
      out += ' ';
      put_effect(out, e.children.front(), -1);
      out += ')';
      return;
    case Kind::Add: put_atom(out, e.atom); return;
    case Kind::Delete: out += "(not "; put_atom(out, e.atom); out += ')'; return;
    case Kind::Numeric:
      out += '(';
      out += to_string(e.assign);
      out += ' ';
      put_atom(out, e.atom);
      out += ' ';
      put_expression(out, *e.value);
      out += ')';
      return;
    case Kind::Timed:
      out += '(';
      out += to_string(e.time);
      out += ' ';
      put_effect(out, e.children.front(), -1);
      out += ')';
      return;
  }
}

void put_duration(std::string& out, const std::vector<DurationConstraint>& duration) {
  auto one = [&](const DurationConstraint& d) {
    if (d.time) out += std::string("(") + to_string(*d.time) + " ";
    out += std::string("(") + to_string(d.comparison) + " ?duration ";
    put_expression(out, d.value);
    out += ')';
    if (d.time) out += ')';
  };
  if (duration.size() == 1) {
    one(duration.front());
    return;
  }
  out += duration.empty() ? "(" : "(and";
  for (const DurationConstraint& d : duration) {
    out += ' ';
    one(d);
  }
  out += ')';
}

void put_requirements(std::string& out, const std::vector<Requirement>& requirements) {
  if (requirements.empty()) return;
  out += "  (:requirements";
  for (const Requirement& r : requirements) out += ' ' + r.name;
  out += ")\n";
}

void put_section_condition(std::string& out, const char* keyword, const Condition& c) {
  out += "  (";
  out += keyword;
  out += ' ';
  put_condition(out, c, 4);
  out += ")\n";
}

// Writes a declaration list (:types, :constants, :objects) one entry a line.
// In PDDL a '- type' applies to every untyped name before it in the same
// list, so an untyped entry followed by a typed one ends the section and a
// new one begins: re-reading concatenates the sections to the same list.
template <typename Entry, typename TypesOf>
void put_declarations(std::string& out, const char* keyword, const std::vector<Entry>& entries, TypesOf types_of) {
  if (entries.empty()) return;
  out += std::string("  (") + keyword;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const TypeNames& types = types_of(entries[i]);
    out += "\n    " + entries[i].name;
    if (!types.empty()) out += " - " + write_type(types);
    const bool next_typed = i + 1 < entries.size() && !types_of(entries[i + 1]).empty();
    if (types.empty() && next_typed) out += std::string(")\n  (") + keyword;
  }
  out += ")\n";
}

void put_action_body(std::string& out, const std::string& keyword, const std::string& name,
                     const std::vector<TypedName>& parameters) {
  out += "  (" + keyword + " " + name + "\n    :parameters (";
  put_typed_list(out, parameters);
  out += ")";
}

}  // namespace

std::string format_number(double value) {
  if (value == 0.0) return "0";  // also folds -0
  char buffer[400];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
  if (ec != std::errc()) return std::isnan(value) ? "0" : "1e308";
  return std::string(buffer, end);
}

std::string write_type(const TypeNames& types) {
  if (types.size() == 1) return types.front();
  std::string out = "(either";
  for (const std::string& t : types) out += ' ' + t;
  return out + ')';
}

std::string write_atom(const Atom& atom) {
  std::string out;
  put_atom(out, atom);
  return out;
}

std::string write_expression(const NumericExpression& expression) {
  std::string out;
  put_expression(out, expression);
  return out;
}

std::string write_condition(const Condition& condition) {
  std::string out;
  put_condition(out, condition, -1);
  return out;
}

std::string write_effect(const Effect& effect) {
  std::string out;
  put_effect(out, effect, -1);
  return out;
}

std::string write_domain(const Domain& d) {
  std::string out = "(define (domain " + d.name + ")\n";
  put_requirements(out, d.requirements);
  put_declarations(out, ":types", d.types, [](const TypeDeclaration& t) -> const TypeNames& { return t.parents; });
  put_declarations(out, ":constants", d.constants, [](const TypedName& c) -> const TypeNames& { return c.types; });
  if (!d.predicates.empty()) {
    out += "  (:predicates";
    for (const PredicateDeclaration& p : d.predicates) {
      out += "\n    (" + p.name + (p.parameters.empty() ? "" : " ");
      put_typed_list(out, p.parameters);
      out += ')';
    }
    out += ")\n";
  }
  if (!d.functions.empty()) {
    out += "  (:functions";
    for (const FunctionDeclaration& f : d.functions) {
      out += "\n    (" + f.name + (f.parameters.empty() ? "" : " ");
      put_typed_list(out, f.parameters);
      out += ") - " + f.value_type;
    }
    out += ")\n";
  }
  if (d.constraints) put_section_condition(out, ":constraints", *d.constraints);
  for (const DerivedPredicate& p : d.derived_predicates) {
    out += "  (:derived (" + p.name + (p.parameters.empty() ? "" : " ");
    put_typed_list(out, p.parameters);
    out += ")\n    ";
    put_condition(out, p.body, 6);
    out += ")\n";
  }
  for (const Action& a : d.actions) {
    put_action_body(out, ":action", a.name, a.parameters);
    if (a.precondition) {
      out += "\n    :precondition ";
      put_condition(out, *a.precondition, 6);
    }
    if (a.effect) {
      out += "\n    :effect ";
      put_effect(out, *a.effect, 6);
    }
    out += ")\n";
  }
  for (const DurativeAction& a : d.durative_actions) {
    put_action_body(out, ":durative-action", a.name, a.parameters);
    out += "\n    :duration ";
    put_duration(out, a.duration);
    if (a.condition) {
      out += "\n    :condition ";
      put_condition(out, *a.condition, 6);
    }
    if (a.effect) {
      out += "\n    :effect ";
      put_effect(out, *a.effect, 6);
    }
    out += ")\n";
  }
  out += ")\n";
  return out;
}

std::string write_problem(const Problem& p) {
  std::string out = "(define (problem " + p.name + ")\n  (:domain " + p.domain_name + ")\n";
  put_requirements(out, p.requirements);
  put_declarations(out, ":objects", p.objects, [](const TypedName& o) -> const TypeNames& { return o.types; });
  out += "  (:init";
  for (const Atom& a : p.init) {
    out += "\n    ";
    put_atom(out, a);
  }
  for (const NumericFact& f : p.numeric_init) {
    out += "\n    (= ";
    put_atom(out, f.function);
    out += ' ' + format_number(f.value) + ')';
  }
  for (const TimedInitialLiteral& til : p.timed_literals) {
    out += "\n    (at " + format_number(til.time) + ' ';
    if (til.numeric_value) {
      out += "(= " + write_atom(til.atom) + ' ' + format_number(*til.numeric_value) + ')';
    } else if (til.positive) {
      put_atom(out, til.atom);
    } else {
      out += "(not " + write_atom(til.atom) + ')';
    }
    out += ')';
  }
  out += ")\n";
  if (p.goal) put_section_condition(out, ":goal", *p.goal);
  if (p.constraints) put_section_condition(out, ":constraints", *p.constraints);
  if (p.metric) {
    out += std::string("  (:metric ") + (p.metric->minimize ? "minimize " : "maximize ");
    put_expression(out, p.metric->expression);
    out += ")\n";
  }
  out += ")\n";
  return out;
}

}  // namespace alplan::pddl
