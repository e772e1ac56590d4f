#include "planner/novelty_table.h"

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
  return novel ? 1 : 2;
}

}  // namespace alplan
