// Rank and sign tests on one sample of paired differences, and the effect
// sizes reported beside them; the definitions, and which reference each
// follows, are at each declaration. Differences within a tolerance of zero
// count as zero and are dropped (Wilcoxon's original convention).
#pragma once

#include <cstddef>
#include <vector>

namespace alplan::stats {

// Wilcoxon's signed-rank test on one sample of differences (a cluster's mean
// each), two-sided, ties averaged: exact below 20 non-zero differences (the
// permutation distribution of the averaged ranks), else the normal
// approximation with tie and continuity corrections.
struct SignedRank {
  std::size_t n = 0;      // non-zero differences
  double w_plus = 0.0;    // sum of the ranks of the positive ones
  double w_minus = 0.0;   // of the negative ones
  double tie_term = 0.0;  // sum of t^3 - t over groups of t tied ranks
  bool exact = true;      // p by enumeration, else the normal approximation
  double p = 1.0;         // two-sided
};
// Differences within tie_tolerance of zero count as zero and are dropped.
SignedRank signed_rank_test(const std::vector<double>& differences, double tie_tolerance = 1e-9);
double wilcoxon_signed_rank_p(const std::vector<double>& differences, double tie_tolerance = 1e-9);

// Ranks 1..n of |values|, ties (the tolerance as in paired_comparison.h's BootstrapOptions)
// averaged: sorted by magnitude, a group runs while a magnitude is within
// tolerance of the group's first one, so the grouping is deterministic.
std::vector<double> absolute_ranks(const std::vector<double>& values, double tie_tolerance);

// Kerby's (2014) simple difference: (W+ - W-) / (W+ + W-); 0 without ranks.
double rank_biserial(const SignedRank& test);
// mean / sample standard deviation; 0 when every value is 0, NaN when the
// deviation is 0 otherwise or fewer than 2 values.
double standardized_mean_difference(const std::vector<double>& values);

// Two-sided exact binomial p.
double sign_test_p(std::size_t positive, std::size_t nonzero);

}  // namespace alplan::stats
