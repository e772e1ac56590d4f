// The subtype relation of a domain's types. Types named only as parents are
// implicitly declared (as most IPC domains assume); every type is a subtype of
// `object`; `(either a b)` parents give multiple inheritance.
#pragma once

#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "pddl_parser/ast.h"

namespace alplan::pddl {

class TypeHierarchy {
 public:
  explicit TypeHierarchy(const Domain& domain);

  bool is_known(const std::string& type) const;
  // Reflexive; true for any known type and "object".
  bool is_subtype(const std::string& type, const std::string& super) const;
  // `type` may stand where `allowed` (an either-list, empty = object) is asked.
  bool fits(const std::string& type, const TypeNames& allowed) const;
  // Two type expressions can denote a common object (one is below the other).
  bool overlaps(const TypeNames& a, const TypeNames& b) const;
  // Types whose ancestors include themselves.
  std::vector<std::string> cyclic_types() const;
  // The proper ancestors of a known type ("object" included); null if unknown.
  const std::unordered_set<std::string>* ancestors(const std::string& type) const {
    auto it = ancestors_.find(type);
    return it == ancestors_.end() ? nullptr : &it->second;
  }
  // Every known type, "object" first, then in order of first mention.
  const std::vector<std::string>& types() const { return order_; }

 private:
  void add(const std::string& type);

  std::vector<std::string> order_;
  std::unordered_map<std::string, std::vector<std::string>> parents_;
  std::unordered_map<std::string, std::unordered_set<std::string>> ancestors_;
};

}  // namespace alplan::pddl
