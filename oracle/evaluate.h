// Formulas and numeric expressions of the AST evaluated in a State, under a
// binding of variables to objects: the textbook semantics of PDDL 2.1's
// goal descriptions (Fox & Long, JAIR 20, 2003, section 4), with quantifiers
// ranging over every object of their type (plain enumeration) and derived
// atoms read from the state's derived closure (derived.h).
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "oracle/state.h"
#include "oracle/world.h"
#include "pddl_parser/ast.h"

namespace alplan::oracle {

// A read of a fluent that has no value: the plan cannot be judged past it
// (VAL stops there too, "Error occurred in validation attempt").
class UndefinedValue : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Binding {
 public:
  void push(const std::string& variable, const std::string& object) { pairs_.emplace_back(variable, object); }
  void pop(std::size_t n = 1) { pairs_.resize(pairs_.size() - n); }
  // The object bound to a variable (the innermost binding); throws when unbound.
  const std::string& operator[](const std::string& variable) const;
  std::size_t size() const { return pairs_.size(); }
  // "?x=o1 ?y=o2": tells apart the instances a forall gives of one formula.
  std::string text() const;

 private:
  std::vector<std::pair<std::string, std::string>> pairs_;
};

// How comparisons are judged. VAL judges `<`, `<=`, `>`, `>=` and `=`
// with a fixed slack (see the README); the brute force judges exactly,
// because the planner promises plans that need no slack.
struct Comparisons {
  double slack = 0.0;
};

struct Scope {
  Scope(World& w, const State& s, Binding& b, Comparisons c = {}) : world(w), state(s), binding(b), comparisons(c) {}
  World& world;
  const State& state;
  Binding& binding;
  Comparisons comparisons;
  std::optional<double> duration;    // ?duration, inside a durative action
  std::optional<double> total_time;  // (total-time), in a metric
  const std::map<std::string, double>* violations = nullptr;  // is-violated, in a metric
  // Set: each preference found false adds 1 to its name's count (VAL counts
  // per evaluation: per occurrence of an action, per instance of a forall).
  std::map<std::string, double>* preference_counts = nullptr;
  // Set instead, in an over-all condition: each preference instance found
  // false is recorded by its identity (the preference's node and the
  // binding) with its name, so that a step counts it once however many
  // happenings it spans (Gerevini & Long 2005: a violated over-all
  // preference of an action's occurrence counts once).
  std::map<std::string, std::string>* preference_instances = nullptr;
};

// The name VAL counts an unnamed preference under.
inline const char* const kAnonymousPreference = "anonymous";

GroundName ground(const pddl::Atom& atom, const Binding& binding);

// Preferences inside the formula count as true: they are soft (their
// violations are counted apart, preferences.h). A timed condition here is a
// caller's error (conditions of durative actions are split by time first).
bool holds(const pddl::Condition& condition, Scope& scope);
double value(const pddl::NumericExpression& expression, Scope& scope);
bool compare(pddl::Comparison op, double left, double right, const Comparisons& comparisons);

}  // namespace alplan::oracle
