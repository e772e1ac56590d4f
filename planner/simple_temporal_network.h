// A simple temporal network (Dechter, Meiri & Pearl 1991) over the time points
// of a partial plan: node 0 is the time origin, every other node a step.
// Constraints are difference constraints t[to] >= t[from] + weight (an upper
// bound t[to] <= t[from] + d is the edge to -> from with weight -d). The
// network keeps the earliest consistent time of every node: the longest path
// from the origin, maintained incrementally in the manner of Bellman-Ford
// (Cesta & Oddi 1996). A positive cycle, or a push on the origin, means the
// constraints cannot all hold.
#pragma once

#include <cstdint>
#include <vector>

namespace alplan {

struct TemporalEdge {
  std::uint32_t from = 0;
  std::uint32_t to = 0;
  double weight = 0.0;
};

class SimpleTemporalNetwork {
 public:
  SimpleTemporalNetwork() : times_(1, 0.0) {}

  std::uint32_t size() const { return static_cast<std::uint32_t>(times_.size()); }
  double earliest(std::uint32_t node) const { return times_[node]; }
  const std::vector<double>& earliest_times() const { return times_; }
  const std::vector<TemporalEdge>& edges() const { return edges_; }

  // Adds `count` nodes (indices size() .. size()+count-1) and constraints
  // among them and existing nodes. Returns false and leaves the network
  // unchanged if the constraints are inconsistent.
  bool add_nodes(std::uint32_t count, const std::vector<TemporalEdge>& edges);
  bool add_node(const std::vector<TemporalEdge>& edges) { return add_nodes(1, edges); }

  // Adds constraints between existing nodes, with the same guarantee.
  bool add_edges(const std::vector<TemporalEdge>& edges);

 private:
  // Raises times along edges from the queued nodes; false on a positive
  // cycle or a push on the origin.
  bool propagate(std::vector<std::uint32_t> queue, std::vector<double>& times) const;

  // Flat, so that copying a network (one per successor) is two memcpys;
  // adjacency is built only when a constraint pushes an earlier node.
  std::vector<double> times_;
  std::vector<TemporalEdge> edges_;
};

}  // namespace alplan
