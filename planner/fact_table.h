// Interns ground atoms and ground function terms as dense ids. The grounder
// fills one with the reachable facts and freezes it into the GroundTask; the
// validator keeps one open, so that it can execute any plan, reachable or not.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "planner/ids.h"
#include "planner/normalized_task.h"

namespace alplan {

// Key of a ground atom or function term: a head id and object ids.
struct GroundKey {
  std::uint32_t head = kNoId;
  std::vector<ObjectId> args;
  bool operator==(const GroundKey&) const = default;
};

struct GroundKeyHash {
  std::size_t operator()(const GroundKey& key) const noexcept;
};

// Copies share their keys until one of them interns a new key (the tasks
// a grounding cache derives share their reference's fact table).
class GroundKeyTable {
 public:
  GroundKeyTable() : data_(std::make_shared<Data>()) {}
  std::uint32_t intern(const GroundKey& key);
  std::optional<std::uint32_t> find(const GroundKey& key) const;
  const GroundKey& key(std::uint32_t id) const { return data_->keys[id]; }
  std::uint32_t size() const { return static_cast<std::uint32_t>(data_->keys.size()); }

 private:
  struct Data {
    std::vector<GroundKey> keys;
    std::unordered_map<GroundKey, std::uint32_t, GroundKeyHash> ids;
  };
  std::shared_ptr<Data> data_;
};

// "(pred a b)" for a fact, "(f a b)" for a numeric variable.
std::string key_name(const GroundKey& key, const std::string& head, const std::vector<std::string>& objects);

}  // namespace alplan
