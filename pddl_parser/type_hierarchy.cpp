#include "pddl_parser/type_hierarchy.h"

namespace alplan::pddl {

TypeHierarchy::TypeHierarchy(const Domain& domain) {
  add("object");
  for (const TypeDeclaration& t : domain.types) {
    add(t.name);
    for (const std::string& parent : t.parents) {
      add(parent);
      parents_[t.name].push_back(parent);
    }
  }
  // Ancestor closure by depth-first search from every type; a cycle simply
  // makes a type its own ancestor, which cyclic_types() reports.
  for (const std::string& type : order_) {
    std::unordered_set<std::string>& seen = ancestors_[type];
    std::vector<std::string> stack(parents_[type].begin(), parents_[type].end());
    while (!stack.empty()) {
      std::string current = std::move(stack.back());
      stack.pop_back();
      if (!seen.insert(current).second) continue;
      auto it = parents_.find(current);
      if (it != parents_.end()) stack.insert(stack.end(), it->second.begin(), it->second.end());
    }
    seen.insert("object");
  }
}

void TypeHierarchy::add(const std::string& type) {
  if (parents_.emplace(type, std::vector<std::string>{}).second) order_.push_back(type);
}

bool TypeHierarchy::is_known(const std::string& type) const { return parents_.count(type) != 0; }

bool TypeHierarchy::is_subtype(const std::string& type, const std::string& super) const {
  if (type == super || super == "object") return true;
  auto it = ancestors_.find(type);
  return it != ancestors_.end() && it->second.count(super) != 0;
}

bool TypeHierarchy::fits(const std::string& type, const TypeNames& allowed) const {
  if (allowed.empty()) return true;
  for (const std::string& a : allowed) {
    if (is_subtype(type, a)) return true;
  }
  return false;
}

bool TypeHierarchy::overlaps(const TypeNames& a, const TypeNames& b) const {
  if (a.empty() || b.empty()) return true;
  for (const std::string& x : a) {
    for (const std::string& y : b) {
      if (is_subtype(x, y) || is_subtype(y, x)) return true;
    }
  }
  return false;
}

std::vector<std::string> TypeHierarchy::cyclic_types() const {
  std::vector<std::string> cyclic;
  for (const std::string& type : order_) {
    auto it = ancestors_.find(type);
    if (type != "object" && it != ancestors_.end() && it->second.count(type)) cyclic.push_back(type);
  }
  return cyclic;
}

}  // namespace alplan::pddl
