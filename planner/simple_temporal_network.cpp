#include "planner/simple_temporal_network.h"

#include <algorithm>

namespace alplan {
namespace {

// Times are compared with this tolerance so that rounding in sums of
// durations does not read as a violated constraint.
constexpr double kTolerance = 1e-9;

}  // namespace

bool SimpleTemporalNetwork::propagate(std::vector<std::uint32_t> queue, std::vector<double>& times) const {
  std::vector<std::uint32_t> first(times.size() + 1, 0);
  for (const TemporalEdge& e : edges_) ++first[e.from + 1];
  for (std::size_t i = 1; i < first.size(); ++i) first[i] += first[i - 1];
  std::vector<TemporalEdge> out(edges_.size());
  std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
  for (const TemporalEdge& e : edges_) out[fill[e.from]++] = e;
  // Label-correcting longest paths; a node corrected more often than there
  // are nodes lies on a positive cycle.
  std::vector<std::uint32_t> corrections(times.size(), 0);
  std::vector<char> queued(times.size(), 0);
  for (std::uint32_t n : queue) queued[n] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::uint32_t n = queue[head];
    queued[n] = 0;
    for (std::uint32_t i = first[n]; i < first[n + 1]; ++i) {
      const TemporalEdge& e = out[i];
      const double candidate = times[n] + e.weight;
      if (candidate <= times[e.to] + kTolerance) continue;
      if (e.to == 0) return false;  // the origin is fixed at 0
      times[e.to] = candidate;
      if (++corrections[e.to] > times.size()) return false;
      if (!queued[e.to]) {
        queued[e.to] = 1;
        queue.push_back(e.to);
      }
    }
  }
  return true;
}

bool SimpleTemporalNetwork::add_nodes(std::uint32_t count, const std::vector<TemporalEdge>& edges) {
  const std::uint32_t first = size();
  std::vector<double> times = times_;
  times.resize(first + count, 0.0);
  const std::size_t old_edges = edges_.size();
  edges_.insert(edges_.end(), edges.begin(), edges.end());
  // Edges from old nodes settle the new ones at once; only what is still
  // violated then needs propagation.
  for (const TemporalEdge& e : edges) {
    if (e.to >= first && e.from < first) times[e.to] = std::max(times[e.to], times[e.from] + e.weight);
  }
  std::vector<std::uint32_t> queue;
  for (const TemporalEdge& e : edges) {
    if (times[e.from] + e.weight > times[e.to] + kTolerance) queue.push_back(e.from);
  }
  if (!queue.empty() && !propagate(queue, times)) {
    edges_.resize(old_edges);
    return false;
  }
  times_ = std::move(times);
  return true;
}

bool SimpleTemporalNetwork::add_edges(const std::vector<TemporalEdge>& edges) {
  const std::size_t old_edges = edges_.size();
  edges_.insert(edges_.end(), edges.begin(), edges.end());
  std::vector<std::uint32_t> queue;
  for (const TemporalEdge& e : edges) {
    if (times_[e.from] + e.weight > times_[e.to] + kTolerance) queue.push_back(e.from);
  }
  if (queue.empty()) return true;
  std::vector<double> times = times_;
  if (!propagate(queue, times)) {
    edges_.resize(old_edges);
    return false;
  }
  times_ = std::move(times);
  return true;
}

}  // namespace alplan
