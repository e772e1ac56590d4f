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
  // A key last written one way in one plan and another way in the other
  // asks different gaps of a later writer: the plans are not comparable.
  for (std::size_t i = 0, j = 0; i < writer_kinds.size() && j < other.writer_kinds.size();) {
    if (writer_kinds[i].first < other.writer_kinds[j].first) {
      ++i;
    } else if (other.writer_kinds[j].first < writer_kinds[i].first) {
      ++j;
    } else {
      if (writer_kinds[i++].second != other.writer_kinds[j++].second) return false;
    }
  }
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

  // Sources, as (id, node, offset). A later writer comes epsilon after a
  // reader since the last write but may coincide with a holder: a holder
  // counts as a reader epsilon earlier, so that one id compares both.
  struct Source {
    std::uint64_t id;
    std::uint32_t node;
    double offset = 0.0;
  };
  std::vector<Source> sources;
  auto ledger_sources = [&](const Ledger& ledger, SourceKind writer, SourceKind touched) {
    // The ledger keeps only the reads since each key's last write.
    for (const Use& r : ledger.reads) {
      sources.push_back({source_id(touched, r.key), node_of_step_[r.step], r.kind == WriteKind::Add ? -epsilon_ : 0.0});
    }
    for (const Use& w : ledger.writers) {
      sources.push_back({source_id(writer, w.key), node_of_step_[w.step]});
      sources.push_back({source_id(touched, w.key), node_of_step_[w.step]});
      result.writer_kinds.emplace_back(source_id(writer, w.key), static_cast<unsigned char>(w.kind));
    }
  };
  ledger_sources(facts_, kFactWriter, kFactTouched);
  ledger_sources(values_, kValueWriter, kValueTouched);
  std::sort(result.writer_kinds.begin(), result.writer_kinds.end());
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
  // Sources of one id side by side, so each target takes their maximum in
  // one pass (no map per target).
  std::stable_sort(sources.begin(), sources.end(), [](const Source& a, const Source& b) { return a.id < b.id; });
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
    for (const Source& source : sources) {
      if (t.longest.empty() || t.longest.back().first != source.id) t.longest.emplace_back(source.id, kNoPath);
      const double path = longest(source.node);
      if (path != kNoPath) t.longest.back().second = std::max(t.longest.back().second, path + source.offset);
    }
    // A key read but not written since the origin also waits for the origin.
    for (auto& [id, value] : t.longest) {
      if (stands_at_origin_when_missing(id)) value = std::max(value, t.to_origin);
    }
    result.targets.push_back(std::move(t));
  }
  return result;
}

}  // namespace alplan
