// Reduces a task on which the planner and the reference semantics disagree:
// drops actions, conditions, effects, initial facts, timed literals, goals
// and constraints one at a time, keeping each drop after which the same
// disagreement remains (delta debugging's one-minimal reduction: Zeller &
// Hildebrandt, "Simplifying and Isolating Failure-Inducing Input", IEEE TSE
// 28(2), 2002, with single-element steps), until no drop keeps it.
#pragma once

#include "benchmarks/differential/differential.h"

namespace alplan::differential {

Disagreement shrink(const Disagreement& found, const DifferentialOptions& options);

}  // namespace alplan::differential
