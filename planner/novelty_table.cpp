#include "planner/novelty_table.h"

#include <bit>
#include <cstring>

namespace alplan {
namespace {

std::uint64_t value_atom(std::size_t variable, double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  // splitmix64's finaliser over the variable and the value's bits.
  std::uint64_t x = bits ^ (static_cast<std::uint64_t>(variable) * 0x9E3779B97F4A7C15ull);
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

}  // namespace

int NoveltyTable::novelty(double h, const SearchState& state) {
  Seen& seen = seen_[h];
  bool novel = false;
  const std::vector<std::uint64_t>& bits = state.bits();
  if (seen.facts.size() < bits.size()) seen.facts.resize(bits.size(), 0);
  for (std::size_t w = 0; w < bits.size(); ++w) {
    if (bits[w] & ~seen.facts[w]) novel = true;
    seen.facts[w] |= bits[w];
  }
  for (const RunningAction& r : state.running()) {
    if (seen.running.size() <= r.action) seen.running.resize(r.action + 1, false);
    if (!seen.running[r.action]) novel = true;
    seen.running[r.action] = true;
  }
  const std::vector<double>& values = state.values();
  for (std::size_t v = 0; v < values.size(); ++v) {
    if (seen.values.insert(value_atom(v, values[v])).second) novel = true;
  }
  // Every state's pairs are recorded, a novel one's too: a later state is
  // new in a pair only if no earlier state of its h held both.
  const bool novel_pair = max_width_ >= 2 && new_pair(seen, state);
  if (novel) return 1;
  if (novel_pair) return 2;
  return max_width_ + 1;
}

bool NoveltyTable::new_pair(Seen& seen, const SearchState& state) {
  const std::vector<std::uint64_t>& bits = state.bits();
  const std::size_t n = bits.size() * 64;
  if (n > pair_fact_limit_ + 63) return false;
  if (seen.pairs.empty()) seen.pairs.assign(n * (n - 1) / 2, false);
  facts_.clear();
  for (std::size_t w = 0; w < bits.size(); ++w) {
    for (std::uint64_t word = bits[w]; word; word &= word - 1) {
      facts_.push_back(static_cast<std::uint32_t>(w * 64 + static_cast<std::size_t>(std::countr_zero(word))));
    }
  }
  bool novel = false;
  for (std::size_t i = 0; i < facts_.size(); ++i) {
    for (std::size_t j = i + 1; j < facts_.size(); ++j) {
      // Row f of the upper triangle starts after the f rows above it.
      const std::size_t f = facts_[i], g = facts_[j];
      const std::size_t at = f * (2 * n - f - 1) / 2 + (g - f - 1);
      if (!seen.pairs[at]) {
        novel = true;
        seen.pairs[at] = true;
      }
    }
  }
  return novel;
}

}  // namespace alplan
