#include "planner/ground_printer.h"

#include <cmath>
#include <ostream>

#include "pddl_parser/writer.h"

namespace alplan {
namespace {

std::string operation(const GroundTask& task, const char* op, const GroundExpression& e) {
  std::string s = std::string("(") + op;
  for (const GroundExpression& operand : e.operands) s += " " + write_expression(task, operand);
  return s + ")";
}

std::string literal(const GroundTask& task, FactId fact, bool positive) {
  return positive ? task.fact_name(fact) : "(not " + task.fact_name(fact) + ")";
}

std::string assignment(const GroundTask& task, const NumericAssignment& a) {
  return std::string("(") + pddl::to_string(a.assign) + " " + task.variable_name(a.variable) + " " +
         write_expression(task, a.value) + ")";
}

void append(std::string& out, const std::string& part) {
  if (!out.empty()) out += ' ';
  out += part;
}

std::string conjunction(const std::string& parts, bool single) {
  if (parts.empty()) return "(and)";
  return single ? parts : "(and " + parts + ")";
}

}  // namespace

std::string write_expression(const GroundTask& task, const GroundExpression& e) {
  using K = GroundExpression::Kind;
  switch (e.kind) {
    case K::Constant: return pddl::format_number(e.value);
    case K::Variable: return task.variable_name(e.variable);
    case K::Add: return operation(task, "+", e);
    case K::Subtract: return operation(task, "-", e);
    case K::Multiply: return operation(task, "*", e);
    case K::Divide: return operation(task, "/", e);
    case K::Negate: return operation(task, "-", e);
    case K::Duration: return "?duration";
    case K::TotalTime: return "(total-time)";
    case K::Undefined: return e.undefined_term;
    case K::IsViolated:
      return "(is-violated " + (task.lifted && e.variable < task.lifted->pddl3.preferences.size()
                                    ? task.lifted->pddl3.preferences[e.variable]
                                    : std::string("?")) + ")";
  }
  return "?";
}

std::string write_comparison(const GroundTask& task, const GroundComparison& c) {
  return std::string("(") + pddl::to_string(c.comparison) + " " + write_expression(task, c.left) + " " +
         write_expression(task, c.right) + ")";
}

std::string write_formula(const GroundTask& task, const GroundFormula& f) {
  using K = GroundFormula::Kind;
  switch (f.kind) {
    case K::True: return "(and)";
    case K::False: return f.reason.empty() ? "(or)" : f.reason;
    case K::Literal: return literal(task, f.fact, f.positive);
    case K::Comparison: return write_comparison(task, f.comparison);
    case K::And:
    case K::Or: {
      std::string s = f.kind == K::And ? "(and" : "(or";
      for (const GroundFormula& child : f.children) s += " " + write_formula(task, child);
      return s + ")";
    }
  }
  return "?";
}

std::string write_condition(const GroundTask& task, const ConditionSet& c) {
  std::string parts;
  std::size_t n = 0;
  if (c.never) {
    append(parts, *c.never);
    ++n;
  }
  for (FactId f : c.positive) append(parts, literal(task, f, true)), ++n;
  for (FactId f : c.negative) append(parts, literal(task, f, false)), ++n;
  for (const GroundComparison& cmp : c.numeric) append(parts, write_comparison(task, cmp)), ++n;
  for (const GroundFormula& f : c.complex) append(parts, write_formula(task, f)), ++n;
  return conjunction(parts, n == 1);
}

std::string write_effects(const GroundTask& task, const HappeningEffects& e) {
  std::string parts;
  std::size_t n = 0;
  for (FactId f : e.add) append(parts, literal(task, f, true)), ++n;
  for (FactId f : e.del) append(parts, literal(task, f, false)), ++n;
  for (const NumericAssignment& a : e.numeric) append(parts, assignment(task, a)), ++n;
  for (const ConditionalEffect& c : e.conditional) {
    HappeningEffects inner{c.add, c.del, c.ghost_del, c.numeric, {}, {}};
    append(parts, "(when " + write_condition(task, c.condition) + " " + write_effects(task, inner) + ")");
    ++n;
  }
  return conjunction(parts, n == 1);
}

void dump(const GroundTask& task, std::ostream& out) {
  out << "; facts: " << task.facts.size() << "\n";
  for (FactId f = 0; f < task.facts.size(); ++f) {
    out << "fact " << f << " " << task.fact_name(f) << (task.is_derived(f) ? " derived" : "") << "\n";
  }
  out << "; numeric variables: " << task.numeric.size() << "\n";
  for (NumericVarId v = 0; v < task.numeric.size(); ++v) {
    const double value = task.initial_values[v];
    out << "variable " << v << " " << task.variable_name(v) << " = "
        << (std::isnan(value) ? std::string("undefined") : pddl::format_number(value)) << "\n";
  }
  out << "; initial state\n";
  for (FactId f : task.initial_facts) out << "init " << task.fact_name(f) << "\n";
  for (const GroundTimedLiteral& til : task.timed_literals) {
    out << "at " << pddl::format_number(til.time) << " " << literal(task, til.fact, til.positive) << "\n";
  }
  out << "; actions: " << task.actions.size() << "\n";
  for (const GroundAction& a : task.actions) {
    out << (a.durative ? "durative-action " : "action ") << task.action_name(a) << "\n";
    for (const GroundDurationConstraint& d : a.duration) {
      out << "  duration (" << pddl::to_string(d.comparison) << " ?duration " << write_expression(task, d.value)
          << ")" << (d.moment == Moment::End ? " at end" : "") << "\n";
    }
    out << "  " << (a.durative ? "at-start " : "precondition ") << write_condition(task, a.at_start) << "\n";
    if (a.durative) {
      out << "  over-all " << write_condition(task, a.over_all) << "\n";
      out << "  at-end " << write_condition(task, a.at_end) << "\n";
      out << "  start-effect " << write_effects(task, a.start) << "\n";
      out << "  end-effect " << write_effects(task, a.end) << "\n";
    } else {
      out << "  effect " << write_effects(task, a.start) << "\n";
    }
  }
  out << "; axioms: " << task.axioms.size() << " in " << task.strata << " strata\n";
  for (const GroundAxiom& ax : task.axioms) {
    out << "axiom stratum " << ax.stratum << " " << task.fact_name(ax.head) << " <- "
        << write_condition(task, ax.body) << "\n";
  }
  out << "goal " << write_condition(task, task.goal) << "\n";
  if (task.metric) {
    out << "metric " << (task.metric->minimize ? "minimize " : "maximize ")
        << write_expression(task, task.metric->expression) << "\n";
  }
}

}  // namespace alplan
