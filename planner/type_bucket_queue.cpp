#include "planner/type_bucket_queue.h"

namespace alplan {

void TypeBucketQueue::push(double h, std::uint32_t g, NodeId node) {
  const Type type{h, g};
  auto [at, added] = index_.try_emplace(type, types_.size());
  if (added) {
    types_.emplace_back();
    keys_.push_back(type);
  }
  types_[at->second].push_back(node);
  ++size_;
}

std::optional<NodeId> TypeBucketQueue::pop() {
  if (types_.empty()) return std::nullopt;
  const std::size_t slot = std::uniform_int_distribution<std::size_t>(0, types_.size() - 1)(random_);
  std::vector<NodeId>& nodes = types_[slot];
  const std::size_t pick = std::uniform_int_distribution<std::size_t>(0, nodes.size() - 1)(random_);
  const NodeId node = nodes[pick];
  nodes[pick] = nodes.back();
  nodes.pop_back();
  --size_;
  if (nodes.empty()) {
    // The last slot moves into the emptied one, so slots stay dense and a
    // draw never lands on an empty type.
    index_.erase(keys_[slot]);
    const std::size_t last = types_.size() - 1;
    if (slot != last) {
      types_[slot] = std::move(types_[last]);
      keys_[slot] = keys_[last];
      index_[keys_[slot]] = slot;
    }
    types_.pop_back();
    keys_.pop_back();
  }
  return node;
}

}  // namespace alplan
