// PartialPlan::interface (partial_plan.h): the longest paths from the points
// where a future constraint can enter the network to those where it can
// leave it.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>

#include "planner/partial_plan.h"

namespace alplan {
namespace {

constexpr double kNoPath = -std::numeric_limits<double>::infinity();
constexpr double kTolerance = 1e-9;

enum SourceKind : std::uint64_t { kFactWriter, kFactTouched, kValueWriter, kValueTouched, kRunStart, kRunEnd };

std::uint64_t source_id(SourceKind kind, std::uint64_t key) { return (static_cast<std::uint64_t>(kind) << 32) | key; }

// A key written in one plan and not in the other stands at the origin there.
bool stands_at_origin_when_missing(std::uint64_t id) {
  const std::uint64_t kind = id >> 32;
  return kind == kFactWriter || kind == kFactTouched || kind == kValueWriter || kind == kValueTouched;
}

}  // namespace

bool PartialPlan::Interface::allows_all_of(const Interface& other) const {
  if (targets.size() != other.targets.size()) return false;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const Target& a = targets[t];
    const Target& b = other.targets[t];
    if (a.to_origin > b.to_origin + kTolerance) return false;
    // Merge the two sorted lists; a missing key reads the origin's value.
    std::size_t i = 0, j = 0;
    while (i < a.longest.size() || j < b.longest.size()) {
      const std::uint64_t ia = i < a.longest.size() ? a.longest[i].first : ~std::uint64_t{0};
      const std::uint64_t ib = j < b.longest.size() ? b.longest[j].first : ~std::uint64_t{0};
      const std::uint64_t id = std::min(ia, ib);
      if (!stands_at_origin_when_missing(id) && ia != ib) return false;  // runs differ
      const double mine = ia == id ? a.longest[i++].second : a.to_origin;
      const double theirs = ib == id ? b.longest[j++].second : b.to_origin;
      if (mine > theirs + kTolerance) return false;
    }
  }
  return true;
}

PartialPlan::Interface PartialPlan::interface(bool timed_literals_remain) const {
  Interface result;
  // Targets: the origin while timed literals remain, then each pending end.
  std::vector<std::pair<std::pair<ActionId, std::uint32_t>, std::uint32_t>> runs;  // ((action, ordinal), pending)
  std::map<ActionId, std::uint32_t> ordinals;
  for (std::uint32_t i = 0; i < pending_.size(); ++i) runs.push_back({{pending_[i].action, ordinals[pending_[i].action]++}, i});
  std::sort(runs.begin(), runs.end());
  std::vector<std::uint32_t> targets;
  if (timed_literals_remain) targets.push_back(0);
  for (const auto& [run, i] : runs) targets.push_back(pending_[i].node);
  if (targets.empty()) return result;

  // Sources, as (id, node).
  std::vector<std::pair<std::uint64_t, std::uint32_t>> sources;
  auto ledger_sources = [&](const Ledger& ledger, SourceKind writer, SourceKind touched) {
    std::map<std::uint32_t, std::vector<std::uint32_t>> readers;  // key -> nodes read since the last write
    for (const Use& r : ledger.reads) {
      const std::optional<std::uint32_t> w = ledger.writer(r.key);
      if (!w || r.step > *w) readers[r.key].push_back(node_of_step_[r.step]);
    }
    for (const Use& w : ledger.writers) {
      sources.push_back({source_id(writer, w.key), node_of_step_[w.step]});
      sources.push_back({source_id(touched, w.key), node_of_step_[w.step]});
    }
    for (const auto& [key, nodes] : readers) {
      for (std::uint32_t n : nodes) sources.push_back({source_id(touched, key), n});
    }
  };
  ledger_sources(facts_, kFactWriter, kFactTouched);
  ledger_sources(values_, kValueWriter, kValueTouched);
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const PendingEnd& p = pending_[runs[r].second];
    sources.push_back({source_id(kRunStart, r), p.start_node});
    sources.push_back({source_id(kRunEnd, r), p.node});
  }

  // Longest paths from each target, by Dijkstra on Johnson's reweighting:
  // the earliest times are potentials (e[v] >= e[u] + w on every edge), so
  // e[u] + w - e[v] <= 0, and a longest path is a shortest one on its negation.
  const std::uint32_t n = network_.size();
  const std::vector<double>& e = network_.earliest_times();
  std::vector<std::vector<std::pair<std::uint32_t, double>>> out(n);
  for (const TemporalEdge& edge : network_.edges()) {
    out[edge.from].emplace_back(edge.to, std::max(0.0, e[edge.to] - e[edge.from] - edge.weight));
  }
  for (std::uint32_t target : targets) {
    std::vector<double> cost(n, std::numeric_limits<double>::infinity());
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    cost[target] = 0.0;
    queue.push({0.0, target});
    while (!queue.empty()) {
      const auto [c, u] = queue.top();
      queue.pop();
      if (c > cost[u]) continue;
      for (const auto& [v, w] : out[u]) {
        if (c + w < cost[v]) {
          cost[v] = c + w;
          queue.push({cost[v], v});
        }
      }
    }
    auto longest = [&](std::uint32_t v) { return std::isfinite(cost[v]) ? e[v] - e[target] - cost[v] : kNoPath; };
    Interface::Target t;
    t.to_origin = longest(0);
    std::map<std::uint64_t, double> by_source;
    for (const auto& [id, node] : sources) {
      auto [it, fresh] = by_source.try_emplace(id, kNoPath);
      it->second = std::max(it->second, longest(node));
    }
    // A key read but not written since the origin also waits for the origin.
    for (auto& [id, value] : by_source) {
      if (stands_at_origin_when_missing(id)) value = std::max(value, t.to_origin);
    }
    t.longest.assign(by_source.begin(), by_source.end());
    result.targets.push_back(std::move(t));
  }
  return result;
}

}  // namespace alplan
