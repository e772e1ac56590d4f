// Type-based exploration (Xie, Müller, Holte & Imai, AAAI 2014, "Type-Based
// Exploration with Multiple Search Queues for Satisficing Planning").
//
// Nodes are grouped by their type, the pair (h, g); a pop draws a type
// uniformly among the non-empty ones, then a node uniformly within it. A
// greedy search that takes every fourth node from here still follows h, but
// also samples regions h ranks low: the states below a dead end the
// relaxation cannot see (storage, sokoban) or a long plateau share a few
// types, so however many nodes they hold they get no more draws than a type
// with one node.
//
// Randomness comes from the queue's own generator, seeded by the caller, so
// a search is reproducible and two searches in one process do not interact.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "planner/search_space.h"

namespace alplan {

class TypeBucketQueue {
 public:
  explicit TypeBucketQueue(std::uint64_t seed) : random_(seed) {}

  // A node of type (h, g). An infinite h (a dead end) is the caller's to drop.
  void push(double h, std::uint32_t g, NodeId node);
  // A node drawn as above and removed; nullopt when empty.
  std::optional<NodeId> pop();
  bool empty() const { return types_.empty(); }
  std::size_t size() const { return size_; }
  std::size_t type_count() const { return types_.size(); }

 private:
  using Type = std::pair<double, std::uint32_t>;
  std::map<Type, std::size_t> index_;          // type -> its slot in types_
  std::vector<std::vector<NodeId>> types_;     // the non-empty types' nodes
  std::vector<Type> keys_;                     // slot -> type, to unindex a slot emptied
  std::size_t size_ = 0;
  std::mt19937_64 random_;
};

}  // namespace alplan
