// Snap actions (Long & Fox 2003; POPF, Coles et al. ICAPS 2010): a durative
// action splits into its start and its end; instantaneous actions and timed
// initial literals are snaps too. The search applies snaps one at a time.
#pragma once

#include <cstdint>
#include <vector>

#include "planner/ids.h"

namespace alplan {

enum class SnapKind : std::uint8_t { Instant, Start, End, TimedLiteral };

struct Snap {
  SnapKind kind = SnapKind::Instant;
  std::uint32_t index = 0;  // ActionId, or the timed literal's index
  bool operator==(const Snap&) const = default;
};

// What a snap reads and writes: the partial order puts every writer of a
// fact or variable after its earlier readers and writers, and every reader
// after its earlier writers (POPF's ordering rules, made uniform).
struct Footprint {
  std::vector<FactId> reads, writes;
  std::vector<NumericVarId> reads_values, writes_values;
};

}  // namespace alplan
