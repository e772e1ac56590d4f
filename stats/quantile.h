// Quantiles of a sample, each named by its method, so that a printed p95
// says which p95 it is (Hyndman & Fan 1996, "Sample quantiles in statistical
// packages", The American Statistician 50:361, number the definitions).
// - nearest_rank: the smallest value with at least a share q of the sample
//   at or below it, the order statistic x_(ceil(q n)) (Hyndman & Fan's
//   definition 1, the inverse of the empirical distribution function). Every
//   latency figure a study reports (p50, p95, max) is this one: it is a value
//   some call actually took, and "95% of the calls took at most the p95"
//   holds by construction.
// - linear_quantile: linear between order statistics, x at position
//   1 + q (n - 1) (definition 7, R's and NumPy's default). The bootstrap's
//   percentile interval uses it, as Davison & Hinkley's percentile method
//   interpolates between resampled statistics.
// Values are taken as given: NaN sorts unpredictably, so a caller leaves it
// out. Both return NaN for an empty sample and throw std::invalid_argument
// for q outside [0, 1].
#pragma once

#include <vector>

namespace alplan::stats {

// q = 0 gives the minimum, q = 1 the maximum.
double nearest_rank(std::vector<double> values, double q);
double linear_quantile(std::vector<double> values, double q);

// The same on a sample already sorted ascending (not checked).
double nearest_rank_of_sorted(const std::vector<double>& sorted, double q);
double linear_quantile_of_sorted(const std::vector<double>& sorted, double q);

}  // namespace alplan::stats
