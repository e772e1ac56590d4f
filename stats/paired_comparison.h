// Paired comparisons for the repair study: every strategy meets the same
// failures, so its result on a run is compared with replan's on the same
// run. The runs come in clusters (the study's homes: several runs a home,
// some of them duplicates of one another), and runs of one cluster are not
// independent, so the cluster is the unit of every inference below. For
// the per-run differences (other minus reference):
// - the mean run-level difference with a 95% percentile cluster bootstrap
//   interval: resample clusters with replacement and take all of each one's
//   runs (Davison & Hinkley 1997, Bootstrap Methods and their Application,
//   sec. 3.8; Field & Welsh 2007, "Bootstrapping clustered data", JRSS B
//   69:369); the statistic of a resample is the mean over its runs;
// - the Wilcoxon signed-rank test on the per-cluster mean differences (one
//   value a cluster), two-sided, zero means dropped (Wilcoxon's original
//   convention), ties averaged; exact below 20 non-zero clusters (the
//   permutation distribution of the averaged ranks, so also with ties),
//   else the normal approximation with tie and continuity corrections;
// - the sign test on the per-cluster means, exact binomial, two-sided;
// - effect sizes on the per-cluster means: the matched-pairs rank-biserial
//   correlation (Kerby 2014, Comprehensive Psychology 3:11.IT.3.1), i.e.
//   (sum of positive ranks - sum of negative ranks) / sum of all ranks,
//   zeros dropped, in [-1, 1]; and d_z, the mean of the cluster means over
//   their standard deviation (n - 1) (Cohen 1988; Lakens 2013, Front.
//   Psychol. 4:863).
// Without cluster ids every pair is its own cluster, which is the plain
// run bootstrap and run-level tests. The tests themselves are in
// rank_tests.h, the corrections for a family in multiple_testing.h.
// A caller testing a family of hypotheses adjusts the p-values with
// holm_adjust (multiple_testing.h) and stores the adjusted signed-rank p in
// `wilcoxon_p_adjusted`. Deterministic for a seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace alplan::stats {

struct PairedComparison {
  std::size_t pairs = 0;     // runs with a value on both sides
  std::size_t nonzero = 0;   // of them, runs that differ
  std::size_t positive = 0;  // runs with other > reference
  std::size_t clusters = 0;           // clusters (homes) with at least one pair
  std::size_t nonzero_clusters = 0;   // of them, clusters whose mean difference is not zero
  std::size_t positive_clusters = 0;  // clusters whose mean difference is positive
  double mean_difference = 0.0;        // over the runs
  double ci_low = 0.0, ci_high = 0.0;  // 95%, cluster bootstrap
  double wilcoxon_p = 1.0;             // on the cluster means
  double sign_p = 1.0;                 // on the cluster means
  double rank_biserial = 0.0;          // Kerby 2014, on the cluster means
  double d_z = 0.0;  // NaN when undefined: under 2 clusters, or equal non-zero cluster means
  // Holm-adjusted within the caller's family; compare_paired knows only a
  // family of one, so it sets this to wilcoxon_p.
  double wilcoxon_p_adjusted = 1.0;
  // The cluster interval excludes zero and the signed-rank test on the
  // cluster means, adjusted for the family, agrees (p < 0.05).
  bool significant() const {
    return pairs > 0 && (ci_low > 0.0 || ci_high < 0.0) && wilcoxon_p_adjusted < 0.05;
  }
};

struct BootstrapOptions {
  int resamples = 2000;
  std::uint64_t seed = 1;
  // A difference within this fraction of the values (at least 1) is zero:
  // rounding in plan text, not a difference between strategies.
  double zero_tolerance = 1e-6;
  // Two absolute differences a, b share a rank when
  // |a - b| <= tie_tolerance * max(1, |a|, |b|): relative to the larger
  // magnitude, absolute (1e-9) below magnitude 1. Means of the same values
  // summed in another order differ in the last bits (-484.999 against
  // -484.99899999999997) and must tie.
  double tie_tolerance = 1e-9;
};

// `reference` and `other` are paired by index and of equal length; pairs
// with a non-finite side are left out. `clusters` names each pair's cluster
// (the same length) or is empty: then each pair is its own cluster. Throws
// std::invalid_argument on mismatched lengths.
PairedComparison compare_paired(const std::vector<double>& reference, const std::vector<double>& other,
                                const std::vector<std::string>& clusters = {}, const BootstrapOptions& options = {});

}  // namespace alplan::stats
