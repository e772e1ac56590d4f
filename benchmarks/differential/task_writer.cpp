#include "benchmarks/differential/task_model.h"

#include <algorithm>
#include <sstream>

namespace alplan::differential {
namespace {

// Always (and ...): VAL's parser refuses a lone numeric effect.
std::string conjunction(const std::vector<std::string>& parts) {
  if (parts.empty()) return "(and)";
  std::string s = "(and";
  for (const std::string& p : parts) s += " " + p;
  return s + ")";
}

void timed(const char* when, const std::vector<std::string>& parts, std::vector<std::string>& out) {
  for (const std::string& p : parts) out.push_back("(" + std::string(when) + " " + p + ")");
}

void write_action(const ActionModel& a, std::ostringstream& d) {
  const std::string parameters = a.parameter ? "?x - obj" : "";
  std::vector<std::string> conditions, effects;
  if (a.durative) {
    timed("at start", a.at_start, conditions);
    timed("over all", a.over_all, conditions);
    timed("at end", a.at_end, conditions);
    timed("at start", a.start_effects, effects);
    timed("at end", a.end_effects, effects);
  } else {
    conditions = a.at_start;
    effects = a.start_effects;
  }
  conditions.insert(conditions.end(), a.conditions.begin(), a.conditions.end());
  effects.insert(effects.end(), a.effects.begin(), a.effects.end());
  if (a.durative) {
    d << "  (:durative-action " << a.name << " :parameters (" << parameters << ")\n    :duration " << a.duration
      << "\n    :condition " << conjunction(conditions) << "\n    :effect " << conjunction(effects) << ")\n";
  } else {
    d << "  (:action " << a.name << " :parameters (" << parameters << ")\n    :precondition "
      << conjunction(conditions) << "\n    :effect " << conjunction(effects) << ")\n";
  }
}

}  // namespace

std::string write_domain(const TaskModel& m) {
  std::ostringstream d;
  d << "(define (domain " << m.name << ")\n  (:requirements";
  for (const std::string& r : m.requirements) d << " " << r;
  d << ")\n  (:types obj)\n";
  if (m.unary > 0) {
    d << "  (:constants";
    for (int o = 1; o <= m.objects; ++o) d << " o" << o;
    d << " - obj)\n";
  }
  d << "  (:predicates";
  for (int f = 0; f < m.facts; ++f) d << " (f" << f << ")";
  for (int g = 0; g < m.unary; ++g) d << " (g" << g << " ?o - obj)";
  if (!m.derived.empty()) d << " (d0)";
  d << ")\n";
  if (m.fluents > 0) {
    d << "  (:functions";
    for (int x = 0; x < m.fluents; ++x) d << " (x" << x << ")";
    d << ")\n";
  }
  for (const std::string& r : m.derived) d << "  " << r << "\n";
  for (const ActionModel& a : m.actions) write_action(a, d);
  d << ")\n";
  return d.str();
}

std::string write_problem(const TaskModel& m) {
  std::ostringstream p;
  p << "(define (problem " << m.name << "-1) (:domain " << m.name << ")\n  (:init";
  for (const std::string& i : m.init) p << " " << i;
  p << ")\n  (:goal " << conjunction(m.goal) << ")\n";
  if (!m.constraints.empty()) p << "  (:constraints " << conjunction(m.constraints) << ")\n";
  p << "  (:metric minimize ";
  if (m.metric_terms.empty()) {
    p << "(total-time)";
  } else {
    p << "(+ (total-time)";
    for (const std::string& t : m.metric_terms) p << " " << t;
    p << ")";
  }
  p << "))\n";
  return p.str();
}

}  // namespace alplan::differential
