// The task as the reference semantics sees it: the parser's AST, the objects
// with their types, and names for ground atoms and fluents. Grounding is
// plain enumeration, on demand: a quantifier or a derived predicate ranges
// over every object of its type, and nothing is ever pruned, so there is no
// grounding analysis here that could be wrong.
//
// Shares nothing with planner/: only the parser's AST and its type
// hierarchy (the subtype relation of the domain's declarations).
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "pddl_parser/ast.h"
#include "pddl_parser/type_hierarchy.h"

namespace alplan::oracle {

// A construct the reference semantics does not judge (continuous change,
// object fluents); the verdict then says so instead of guessing.
class NotJudged : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A ground atom or fluent: its name and arguments, as one key.
struct GroundName {
  std::string name;
  std::vector<std::string> args;
  bool operator<(const GroundName& o) const { return name != o.name ? name < o.name : args < o.args; }
  bool operator==(const GroundName& o) const = default;
};
std::string to_string(const GroundName& g);  // "(name a b)"

// Numbers for ground atoms and fluents, handed out on first use. The table
// only grows; an id stays valid for the World's lifetime.
class NameTable {
 public:
  int id(const GroundName& name);
  const GroundName& name(int id) const { return names_[static_cast<std::size_t>(id)]; }
  int size() const { return static_cast<int>(names_.size()); }

 private:
  std::map<GroundName, int> ids_;
  std::vector<GroundName> names_;
};

class World {
 public:
  World(std::shared_ptr<const pddl::Domain> domain, std::shared_ptr<const pddl::Problem> problem);

  const pddl::Domain& domain() const { return *domain_; }
  const pddl::Problem& problem() const { return *problem_; }

  // Every object (constants and problem objects) of a type expression, in
  // declaration order; empty expression: every object.
  const std::vector<std::string>& objects_of(const pddl::TypeNames& types);
  bool is_object(const std::string& name) const { return object_types_.count(name) != 0; }
  bool object_fits(const std::string& object, const pddl::TypeNames& types) const;

  const pddl::Action* action(const std::string& name) const;
  const pddl::DurativeAction* durative_action(const std::string& name) const;
  // The rules deriving a predicate (several rules for one head are a
  // disjunction); empty for a basic predicate.
  std::vector<const pddl::DerivedPredicate*> derived_rules(const std::string& predicate) const;
  bool is_derived(const std::string& predicate) const { return derived_names_.count(predicate) != 0; }

  NameTable& atoms() { return atoms_; }
  NameTable& fluents() { return fluents_; }

 private:
  std::shared_ptr<const pddl::Domain> domain_;
  std::shared_ptr<const pddl::Problem> problem_;
  pddl::TypeHierarchy types_;
  std::vector<std::string> object_order_;
  std::unordered_map<std::string, std::vector<std::string>> object_types_;
  std::map<pddl::TypeNames, std::vector<std::string>> objects_by_type_;
  std::unordered_set<std::string> derived_names_;
  NameTable atoms_, fluents_;
};

}  // namespace alplan::oracle
