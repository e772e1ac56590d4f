#include "planner/fact_table.h"

namespace alplan {

std::size_t GroundKeyHash::operator()(const GroundKey& key) const noexcept {
  std::size_t h = key.head * 0x9E3779B97F4A7C15ull;
  for (ObjectId o : key.args) h = (h ^ o) * 0x100000001B3ull + (h >> 29);
  return h;
}

std::uint32_t GroundKeyTable::intern(const GroundKey& key) {
  // Look up first: most keys the reachability fixpoint interns are known
  // already, and emplace would build (and throw away) a node for each.
  if (const auto it = ids_.find(key); it != ids_.end()) return it->second;
  const auto id = static_cast<std::uint32_t>(keys_.size());
  ids_.emplace(key, id);
  keys_.push_back(key);
  return id;
}

std::optional<std::uint32_t> GroundKeyTable::find(const GroundKey& key) const {
  auto it = ids_.find(key);
  if (it == ids_.end()) return std::nullopt;
  return it->second;
}

std::string key_name(const GroundKey& key, const std::string& head, const std::vector<std::string>& objects) {
  std::string s = "(" + head;
  for (ObjectId o : key.args) s += " " + objects[o];
  return s + ")";
}

}  // namespace alplan
