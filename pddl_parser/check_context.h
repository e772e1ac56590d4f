// Internal to the checker: the declarations of a domain (and the objects of
// a problem) by name, and the checks of atoms, terms, conditions and effects
// against them within a scope of variables.
#pragma once

#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "pddl_parser/ast.h"
#include "pddl_parser/source_location.h"
#include "pddl_parser/type_hierarchy.h"

namespace alplan::pddl::detail {

struct Declarations {
  explicit Declarations(const Domain& domain) : types(domain) {}

  TypeHierarchy types;
  std::unordered_map<std::string, const PredicateDeclaration*> predicates;
  std::unordered_map<std::string, const FunctionDeclaration*> functions;
  std::unordered_set<std::string> derived;
  // Constants, and in a problem also its objects, with their types.
  std::unordered_map<std::string, TypeNames> objects;
  bool in_problem = false;
};

// Warns about each construct the domain uses without its :requirements flag
// (check_requirements.cpp), once per flag, at its first use.
void warn_missing_requirements(const Domain& domain, DiagnosticSink& sink);

// Where a formula stands; decides which constructs are allowed.
enum class Place {
  Precondition,
  DurativeCondition,
  Goal,
  DerivedBody,
  Constraint,
  Effect,
  DurativeEffect,
  Metric,
};

class FormulaChecker {
 public:
  FormulaChecker(const Declarations& declarations, DiagnosticSink& sink)
      : declarations_(declarations), sink_(sink) {}

  void set_scope(const std::vector<TypedName>& parameters, std::string owner);
  void check_condition(const Condition& condition, Place place);
  void check_effect(const Effect& effect, Place place);
  void check_expression(const NumericExpression& expression, Place place);
  // A ground atom of the initial state or a timed initial literal.
  void check_ground_atom(const Atom& atom, const char* what);
  void check_ground_function(const FunctionTerm& function);

 private:
  struct Variable {
    std::string name;
    TypeNames types;
  };

  void condition(const Condition& c, Place place, bool timed);
  void effect(const Effect& e, Place place, bool timed);
  void atom_against(const Atom& atom, const std::vector<TypedName>& parameters, const char* what);
  void term(const Term& t, const TypeNames& allowed, const Atom& atom, std::size_t index, const char* what);
  void push(const std::vector<TypedName>& variables);
  void pop(std::size_t count) { scope_.resize(scope_.size() - count); }
  const Variable* find_variable(const std::string& name) const;

  const Declarations& declarations_;
  DiagnosticSink& sink_;
  std::vector<Variable> scope_;
  std::string owner_;  // "action move", for messages
};

// " (did you mean 'x'?)" for the closest of `candidates` to `name`, or empty
// when nothing is close.
std::string did_you_mean(const std::string& name, const std::vector<std::string>& candidates);

template <typename Map>
std::vector<std::string> keys_of(const Map& map) {
  std::vector<std::string> keys;
  keys.reserve(map.size());
  for (const auto& entry : map) keys.push_back(entry.first);
  return keys;
}

}  // namespace alplan::pddl::detail
