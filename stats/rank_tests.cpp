#include "stats/rank_tests.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace alplan::stats {
namespace {

bool within(double a, double b, double tolerance) {
  return std::fabs(a - b) <= tolerance * std::max({1.0, std::fabs(a), std::fabs(b)});
}

// Ranks of |values| and the ties' sum of t^3 - t (the variance correction).
std::vector<double> ranks_and_ties(const std::vector<double>& values, double tolerance, double* tie_term) {
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  // Stable, so equal magnitudes keep their input order: the same ranks
  // for the same input, whatever the standard library's sort.
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return std::fabs(values[a]) < std::fabs(values[b]); });
  std::vector<double> ranks(values.size());
  *tie_term = 0.0;
  for (std::size_t i = 0; i < order.size();) {
    // Against the group's first magnitude, not the previous one, so that a
    // chain of near values cannot stretch one group without bound.
    const double first = std::fabs(values[order[i]]);
    std::size_t j = i;
    while (j + 1 < order.size() && within(std::fabs(values[order[j + 1]]), first, tolerance)) ++j;
    const double average = (static_cast<double>(i + 1) + static_cast<double>(j + 1)) / 2.0;
    for (std::size_t k = i; k <= j; ++k) ranks[order[k]] = average;
    const double t = static_cast<double>(j - i + 1);
    *tie_term += t * t * t - t;
    i = j + 1;
  }
  return ranks;
}

// Two-sided p of W+ by enumerating the 2^n sign assignments of the ranks
// (conditional on the tie pattern). Averaged ranks are multiples of 1/2,
// so doubled they are integers and a subset-sum count is exact.
double exact_two_sided(const std::vector<double>& ranks, double w_plus) {
  std::vector<std::size_t> doubled;
  std::size_t total = 0;
  for (double r : ranks) {
    doubled.push_back(static_cast<std::size_t>(std::lround(2.0 * r)));
    total += doubled.back();
  }
  std::vector<double> ways(total + 1, 0.0);
  ways[0] = 1.0;
  for (std::size_t r : doubled) {
    for (std::size_t s = total; s >= r; --s) ways[s] += ways[s - r];
  }
  // The null distribution is symmetric about total / 2: the smaller tail doubled.
  const auto w = static_cast<std::size_t>(std::lround(2.0 * w_plus));
  const std::size_t tail_end = std::min(w, total - w);
  double below = 0.0;
  for (std::size_t s = 0; s <= tail_end; ++s) below += ways[s];
  return std::min(1.0, 2.0 * below / std::ldexp(1.0, static_cast<int>(ranks.size())));
}

}  // namespace

std::vector<double> absolute_ranks(const std::vector<double>& values, double tie_tolerance) {
  double tie_term = 0.0;
  return ranks_and_ties(values, tie_tolerance, &tie_term);
}

SignedRank signed_rank_test(const std::vector<double>& differences, double tie_tolerance) {
  std::vector<double> d;
  for (double x : differences) {
    if (std::isfinite(x) && !within(x, 0.0, tie_tolerance)) d.push_back(x);
  }
  SignedRank t;
  t.n = d.size();
  if (t.n == 0) return t;
  const std::vector<double> ranks = ranks_and_ties(d, tie_tolerance, &t.tie_term);
  for (std::size_t i = 0; i < t.n; ++i) (d[i] > 0 ? t.w_plus : t.w_minus) += ranks[i];
  t.exact = t.n < 20;
  if (t.exact) {
    t.p = exact_two_sided(ranks, t.w_plus);
    return t;
  }
  const double n = static_cast<double>(t.n);
  const double variance = n * (n + 1.0) * (2.0 * n + 1.0) / 24.0 - t.tie_term / 48.0;
  if (variance <= 0.0) return t;
  const double z = std::max(0.0, std::fabs(t.w_plus - n * (n + 1.0) / 4.0) - 0.5) / std::sqrt(variance);
  t.p = std::erfc(z / std::sqrt(2.0));
  return t;
}

double wilcoxon_signed_rank_p(const std::vector<double>& differences, double tie_tolerance) {
  return signed_rank_test(differences, tie_tolerance).p;
}

double rank_biserial(const SignedRank& test) {
  const double all = test.w_plus + test.w_minus;
  return all > 0.0 ? (test.w_plus - test.w_minus) / all : 0.0;
}

double standardized_mean_difference(const std::vector<double>& values) {
  if (std::all_of(values.begin(), values.end(), [](double x) { return x == 0.0; })) return 0.0;
  if (values.size() < 2) return std::nan("");
  const double n = static_cast<double>(values.size());
  const double mean = std::accumulate(values.begin(), values.end(), 0.0) / n;
  double squares = 0.0;
  for (double x : values) squares += (x - mean) * (x - mean);
  const double sd = std::sqrt(squares / (n - 1.0));
  return sd > 0.0 ? mean / sd : std::nan("");
}

double sign_test_p(std::size_t positive, std::size_t nonzero) {
  if (nonzero == 0) return 1.0;
  const std::size_t k = std::min(positive, nonzero - positive);
  double tail = 0.0;
  for (std::size_t i = 0; i <= k; ++i) {
    const double log_choose = std::lgamma(static_cast<double>(nonzero) + 1.0) - std::lgamma(static_cast<double>(i) + 1.0) -
                              std::lgamma(static_cast<double>(nonzero - i) + 1.0);
    tail += std::exp(log_choose - static_cast<double>(nonzero) * std::log(2.0));
  }
  return std::min(1.0, 2.0 * tail);
}

}  // namespace alplan::stats
