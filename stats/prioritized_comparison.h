// Intention to treat for paired comparisons where a strategy can fail:
// generalized pairwise comparisons of prioritized outcomes (Buyse 2010,
// "Generalized pairwise comparisons of prioritized outcomes in the
// two-sample problem", Statistics in Medicine 29:3245; a failure ranked worse
// than any success, as in Lachin's 1999 worst-rank scores, Controlled
// Clinical Trials 20:408). Each pair (one perturbation, the reference's
// outcome and the other's) is compared on the first outcome that tells them
// apart: success first (a repair beats none), then, where both succeeded, the
// value (lower is better: plan distance, makespan). The pair scores +1 where
// the other strategy wins, -1 where the reference wins, 0 for a tie. The net
// benefit is the mean score, P(win) - P(loss), in [-1, 1]; its interval and
// tests are paired_comparison.h's on the scores against 0 (clusters
// resampled, the signed-rank test on cluster means). No pair is left out:
// a strategy that fails on the hard cases pays for it here, where a
// comparison on the perturbations every strategy repaired would not count
// them at all.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "stats/paired_comparison.h"

namespace alplan::stats {

struct PrioritizedOutcome {
  bool success = false;
  double value = 0.0;  // read only where success; lower is better
};

// +1 other wins, -1 reference wins, 0 tie; values within `tolerance` of
// each other (relative to the larger, at least 1) tie.
int prioritized_score(const PrioritizedOutcome& reference, const PrioritizedOutcome& other, double tolerance = 1e-6);

struct NetBenefit {
  std::size_t wins = 0, ties = 0, losses = 0;  // of the other strategy, pair by pair
  PairedComparison scores;  // mean_difference is the net benefit
};

// `reference` and `other` are paired by index (equal lengths), `clusters`
// as in compare_paired. Throws std::invalid_argument on mismatched lengths.
NetBenefit net_benefit(const std::vector<PrioritizedOutcome>& reference, const std::vector<PrioritizedOutcome>& other,
                       const std::vector<std::string>& clusters = {}, const BootstrapOptions& options = {});

}  // namespace alplan::stats
