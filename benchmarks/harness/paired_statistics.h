// Paired comparisons for the repair study: every strategy meets the same
// failures, so its result on a run is compared with replan's on the same
// run. For the per-run differences (other minus reference):
// - the mean difference with a 95% percentile bootstrap confidence interval
//   (resampling runs, Efron & Tibshirani 1993, ch. 13);
// - the Wilcoxon signed-rank test, two-sided, zero differences dropped,
//   tied ranks averaged, normal approximation with tie and continuity
//   corrections (exact enumeration below 20 non-zero pairs without ties);
// - the sign test, exact binomial, two-sided.
// Deterministic for a seed.
#pragma once

#include <cstdint>
#include <vector>

namespace alplan::bench {

struct PairedComparison {
  std::size_t pairs = 0;     // runs with a value on both sides
  std::size_t nonzero = 0;   // of them, runs that differ
  std::size_t positive = 0;  // other > reference
  double mean_difference = 0.0;
  double ci_low = 0.0, ci_high = 0.0;  // 95%
  double wilcoxon_p = 1.0;
  double sign_p = 1.0;
  // The interval excludes zero and the signed-rank test agrees (p < 0.05).
  bool significant() const { return pairs > 0 && (ci_low > 0.0 || ci_high < 0.0) && wilcoxon_p < 0.05; }
};

struct BootstrapOptions {
  int resamples = 2000;
  std::uint64_t seed = 1;
  // A difference within this fraction of the values (at least 1) is zero.
  double zero_tolerance = 1e-6;
};

// `reference` and `other` are paired by index and of equal length.
PairedComparison compare_paired(const std::vector<double>& reference, const std::vector<double>& other,
                                const BootstrapOptions& options = {});

// Two-sided p-values on the differences alone (exposed for tests).
double wilcoxon_signed_rank_p(const std::vector<double>& differences);
double sign_test_p(std::size_t positive, std::size_t nonzero);

}  // namespace alplan::bench
