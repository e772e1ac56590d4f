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
  if (const auto it = data_->ids.find(key); it != data_->ids.end()) return it->second;
  // As in SharedVector: only a table's owner interns, so a count of one
  // cannot grow meanwhile.
  if (data_.use_count() > 1) data_ = std::make_shared<Data>(*data_);
  const auto id = static_cast<std::uint32_t>(data_->keys.size());
  data_->ids.emplace(key, id);
  data_->keys.push_back(key);
  return id;
}

std::optional<std::uint32_t> GroundKeyTable::find(const GroundKey& key) const {
  auto it = data_->ids.find(key);
  if (it == data_->ids.end()) return std::nullopt;
  return it->second;
}

std::string key_name(const GroundKey& key, const std::string& head, const std::vector<std::string>& objects) {
  std::string s = "(" + head;
  for (ObjectId o : key.args) s += " " + objects[o];
  return s + ")";
}

}  // namespace alplan
