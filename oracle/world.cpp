#include "oracle/world.h"

#include <algorithm>

namespace alplan::oracle {

std::string to_string(const GroundName& g) {
  std::string s = "(" + g.name;
  for (const std::string& a : g.args) s += " " + a;
  return s + ")";
}

int NameTable::id(const GroundName& name) {
  auto [it, fresh] = ids_.emplace(name, static_cast<int>(names_.size()));
  if (fresh) names_.push_back(name);
  return it->second;
}

World::World(std::shared_ptr<const pddl::Domain> domain, std::shared_ptr<const pddl::Problem> problem)
    : domain_(std::move(domain)), problem_(std::move(problem)), types_(*domain_) {
  auto declare = [&](const pddl::TypedName& o) {
    auto [it, fresh] = object_types_.emplace(o.name, std::vector<std::string>{});
    if (fresh) object_order_.push_back(o.name);
    for (const std::string& t : o.types) {
      if (std::find(it->second.begin(), it->second.end(), t) == it->second.end()) it->second.push_back(t);
    }
  };
  for (const pddl::TypedName& c : domain_->constants) declare(c);
  for (const pddl::TypedName& o : problem_->objects) declare(o);
  for (const pddl::DerivedPredicate& d : domain_->derived_predicates) derived_names_.insert(d.name);
  for (const pddl::FunctionDeclaration& f : domain_->functions) {
    if (f.value_type != "number") throw NotJudged("object fluent (" + f.name + ") - " + f.value_type);
  }
}

bool World::object_fits(const std::string& object, const pddl::TypeNames& wanted) const {
  if (wanted.empty()) return true;
  auto it = object_types_.find(object);
  if (it == object_types_.end()) return false;
  if (it->second.empty()) return types_.fits("object", wanted);
  // An object declared `- (either a b)` is of type a or b: it fits where
  // either does (VAL's reading of either in object declarations).
  return std::any_of(it->second.begin(), it->second.end(),
                     [&](const std::string& t) { return types_.fits(t, wanted); });
}

const std::vector<std::string>& World::objects_of(const pddl::TypeNames& wanted) {
  auto it = objects_by_type_.find(wanted);
  if (it != objects_by_type_.end()) return it->second;
  std::vector<std::string> out;
  for (const std::string& o : object_order_) {
    if (object_fits(o, wanted)) out.push_back(o);
  }
  return objects_by_type_.emplace(wanted, std::move(out)).first->second;
}

const pddl::Action* World::action(const std::string& name) const {
  for (const pddl::Action& a : domain_->actions) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

const pddl::DurativeAction* World::durative_action(const std::string& name) const {
  for (const pddl::DurativeAction& a : domain_->durative_actions) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

std::vector<const pddl::DerivedPredicate*> World::derived_rules(const std::string& predicate) const {
  std::vector<const pddl::DerivedPredicate*> rules;
  for (const pddl::DerivedPredicate& d : domain_->derived_predicates) {
    if (d.name == predicate) rules.push_back(&d);
  }
  return rules;
}

}  // namespace alplan::oracle
