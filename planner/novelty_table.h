// Novelty of a state (width 1, or 2 with pairs of facts) within its
// heuristic partition, the measure of best-first width search (Lipovetzky &
// Geffner, AAAI 2017, "Best-First Width Search: Exploration and Exploitation
// in Classical Planning") with states partitioned by their h as in Katz,
// Lipovetzky, Moshkovich & Tuisov (ICAPS 2017, "Adapting Novelty to Classical
// Planning as Heuristic Search").
//
// A state is novel (novelty 1) when it holds an atom no earlier state of the
// same h held; otherwise, at width 1, its novelty is 2 (not told apart).
// Ordering a greedy queue by (novelty, h) sends it first to states that make
// something new true at their level of h: on a plateau where every step
// lowers h into a dead end the relaxation cannot see (storage's sealed
// depots, floor-tile's walled robots), the states that differ from those
// already tried go first instead of the siblings of the trap.
//
// With width 2, a state that holds no new atom but a pair of facts no
// earlier state of its h held together has novelty 2, and the rest 3: the
// pairs tell apart states that width 1 lumps together (storage 2011, where
// every crate and every cell has been seen at every h, and what differs is
// which crate sits where). Pairs are kept for facts only and only up to a
// number of facts, their table growing with its square.
//
// Atoms: the facts, the running actions (as COLIN's state holds them), and
// the pairs (numeric variable, value); the timed initial literal reached is
// not one (it only moves forward). Each call records the state's atoms and
// pairs, so the answer depends on the order of the calls: the caller asks
// once per node, when it is queued.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "planner/search_state.h"

namespace alplan {

class NoveltyTable {
 public:
  // max_width 2 also tracks pairs of facts, where the task has at most
  // pair_fact_limit facts (their table grows with the square).
  explicit NoveltyTable(int max_width = 1, std::size_t pair_fact_limit = 2000)
      : max_width_(max_width), pair_fact_limit_(pair_fact_limit) {}
  // 1 when the state holds an atom not seen before under this h; else 2
  // when it holds a new pair of facts (max_width 2); else max_width + 1.
  int novelty(double h, const SearchState& state);
  std::size_t partitions() const { return seen_.size(); }

 private:
  struct Seen {
    std::vector<std::uint64_t> facts;  // a bit per fact, as SearchState stores them
    std::vector<bool> running;         // per action id
    std::unordered_set<std::uint64_t> values;  // (variable, value) hashed
    std::vector<bool> pairs;                   // (f, g), f < g: the upper triangle, row by row
  };
  bool new_pair(Seen& seen, const SearchState& state);
  int max_width_;
  std::size_t pair_fact_limit_;
  std::vector<std::uint32_t> facts_;  // scratch: the state's facts
  std::unordered_map<double, Seen> seen_;
};

}  // namespace alplan
