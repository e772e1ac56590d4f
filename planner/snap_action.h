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
//
// How far apart follows VAL's mutex rule (Fox & Long 2003, section 8.2;
// VAL's Ownership.cpp): a snap that reads (a condition) what another writes,
// or writes it another way, must not share its happening, so they are
// epsilon apart. Two snaps that both add a fact, both delete it, or both
// increase or decrease a variable may share one (additive changes
// commute); and an over-all condition is no read at all in that rule: it is
// checked on the open interval, after its start's happening and before its
// end's. Those pairs are ordered but may coincide (a gap of 0): an invariant
// given by a timed literal at the start's own time, a holder ending with the
// provider that deletes its fact (issue 42's cases 3 and 4).
struct Footprint {
  std::vector<FactId> reads, writes;
  std::vector<NumericVarId> reads_values, writes_values;
  // Over-all conditions of a start or end, where not also read: ordered
  // after their last writer and before later writers, with no gap.
  std::vector<FactId> holds;
  std::vector<NumericVarId> holds_values;
  // Writes of one polarity only (a fact both added and deleted, plainly or
  // by a conditional effect, is in neither): such writers of one key may
  // share a happening with each other.
  std::vector<FactId> adds, dels;
  std::vector<NumericVarId> additive_values;  // only increased or decreased
  // What the conditions of conditional effects that do not fire read (a
  // snap's quiet footprint, TaskIndex::footprint): VAL reads such a
  // condition in the state before the happening and counts it as no read
  // when it is false, so later members may write it; but the search
  // evaluates it where the snap stands in the happening, so writers before
  // it stay epsilon apart.
  std::vector<FactId> reads_first;
  std::vector<NumericVarId> reads_first_values;
};

}  // namespace alplan
