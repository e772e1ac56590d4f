#include "planner/type_bucket_queue.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <vector>

using namespace alplan;

namespace {

std::vector<NodeId> drain(TypeBucketQueue& q) {
  std::vector<NodeId> out;
  while (std::optional<NodeId> id = q.pop()) out.push_back(*id);
  return out;
}

}  // namespace

TEST_CASE("the type-based queue gives back every node once") {
  TypeBucketQueue q(7);
  for (NodeId id = 0; id < 300; ++id) q.push(static_cast<double>(id % 7), id % 5, id);
  CHECK(q.size() == 300);
  CHECK(q.type_count() == 35);
  const std::vector<NodeId> out = drain(q);
  CHECK(q.empty());
  CHECK(q.size() == 0);
  CHECK(q.type_count() == 0);
  REQUIRE(out.size() == 300);
  CHECK(std::set<NodeId>(out.begin(), out.end()).size() == 300);
  CHECK_FALSE(q.pop());
}

TEST_CASE("the type-based queue draws a type, not a node: a lone node is not drowned by a crowded type") {
  TypeBucketQueue q(1);
  for (NodeId id = 0; id < 10000; ++id) q.push(4.0, 12, id);  // a plateau: one type
  q.push(9.0, 3, 10000);                                      // one node h ranks last
  // Each draw picks either type with probability 1/2; drawn by nodes, the
  // lone one would wait about 5,000 draws.
  std::size_t draws = 0;
  while (q.pop() != std::optional<NodeId>(10000)) ++draws;
  CHECK(draws < 30);
  CHECK(q.type_count() == 1);
}

TEST_CASE("the type-based queue is reproducible by its seed and pushes after pops are seen") {
  auto run = [](std::uint64_t seed) {
    TypeBucketQueue q(seed);
    std::vector<NodeId> out;
    NodeId next = 0;
    for (int round = 0; round < 50; ++round) {
      for (int k = 0; k < 3; ++k, ++next) q.push(static_cast<double>(next % 4), next % 3, next);
      out.push_back(*q.pop());
    }
    for (NodeId id : drain(q)) out.push_back(id);
    return out;
  };
  const std::vector<NodeId> a = run(3);
  CHECK(a == run(3));
  CHECK(a != run(4));
  std::vector<NodeId> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  for (NodeId id = 0; id < sorted.size(); ++id) CHECK(sorted[id] == id);
}
