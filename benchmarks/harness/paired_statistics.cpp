#include "benchmarks/harness/paired_statistics.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace alplan::bench {
namespace {

double percentile_of_sorted(const std::vector<double>& sorted, double p) {
  const double rank = p * static_cast<double>(sorted.size() - 1);
  const auto low = static_cast<std::size_t>(std::floor(rank));
  const std::size_t high = std::min(sorted.size() - 1, low + 1);
  return sorted[low] + (rank - static_cast<double>(low)) * (sorted[high] - sorted[low]);
}

// Ranks of |d| from 1, ties averaged; also whether any tie occurred.
std::vector<double> absolute_ranks(const std::vector<double>& d, double* tie_term) {
  std::vector<std::size_t> order(d.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return std::fabs(d[a]) < std::fabs(d[b]); });
  std::vector<double> ranks(d.size());
  *tie_term = 0.0;
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && std::fabs(d[order[j + 1]]) == std::fabs(d[order[i]])) ++j;
    const double average = (static_cast<double>(i + 1) + static_cast<double>(j + 1)) / 2.0;
    for (std::size_t k = i; k <= j; ++k) ranks[order[k]] = average;
    const double t = static_cast<double>(j - i + 1);
    *tie_term += t * t * t - t;
    i = j + 1;
  }
  return ranks;
}

// P(W+ <= w) under the null, by counting subsets of ranks 1..n.
double exact_lower_tail(std::size_t n, double w) {
  const std::size_t total = n * (n + 1) / 2;
  std::vector<double> ways(total + 1, 0.0);
  ways[0] = 1.0;
  for (std::size_t r = 1; r <= n; ++r) {
    for (std::size_t s = total; s >= r; --s) ways[s] += ways[s - r];
  }
  double below = 0.0;
  for (std::size_t s = 0; s <= total && static_cast<double>(s) <= w + 1e-9; ++s) below += ways[s];
  return below / std::ldexp(1.0, static_cast<int>(n));
}

}  // namespace

double wilcoxon_signed_rank_p(const std::vector<double>& differences) {
  std::vector<double> d;
  for (double x : differences) {
    if (x != 0.0 && std::isfinite(x)) d.push_back(x);
  }
  const std::size_t n = d.size();
  if (n == 0) return 1.0;
  double tie_term = 0.0;
  const std::vector<double> ranks = absolute_ranks(d, &tie_term);
  double w_plus = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (d[i] > 0) w_plus += ranks[i];
  }
  const double nn = static_cast<double>(n);
  const double mean = nn * (nn + 1.0) / 4.0;
  if (n < 20 && tie_term == 0.0) {
    const double w = std::min(w_plus, nn * (nn + 1.0) / 2.0 - w_plus);
    return std::min(1.0, 2.0 * exact_lower_tail(n, w));
  }
  const double variance = nn * (nn + 1.0) * (2.0 * nn + 1.0) / 24.0 - tie_term / 48.0;
  if (variance <= 0.0) return 1.0;
  const double z = std::max(0.0, std::fabs(w_plus - mean) - 0.5) / std::sqrt(variance);
  return std::erfc(z / std::sqrt(2.0));
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

PairedComparison compare_paired(const std::vector<double>& reference, const std::vector<double>& other,
                                const BootstrapOptions& options) {
  if (reference.size() != other.size()) throw std::invalid_argument("paired samples of different sizes");
  PairedComparison c;
  std::vector<double> d;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    if (!std::isfinite(reference[i]) || !std::isfinite(other[i])) continue;
    // Times that went through plan text (an external planner's) differ in
    // the last digits: rounding, not a difference between strategies.
    const double scale = std::max({1.0, std::fabs(reference[i]), std::fabs(other[i])});
    const double difference = other[i] - reference[i];
    d.push_back(std::fabs(difference) <= options.zero_tolerance * scale ? 0.0 : difference);
  }
  c.pairs = d.size();
  if (d.empty()) return c;
  double sum = 0.0;
  for (double x : d) {
    sum += x;
    c.nonzero += x != 0.0 ? 1 : 0;
    c.positive += x > 0.0 ? 1 : 0;
  }
  c.mean_difference = sum / static_cast<double>(d.size());
  std::mt19937_64 random(options.seed);
  std::uniform_int_distribution<std::size_t> pick(0, d.size() - 1);
  std::vector<double> means;
  means.reserve(static_cast<std::size_t>(options.resamples));
  for (int r = 0; r < options.resamples; ++r) {
    double s = 0.0;
    for (std::size_t i = 0; i < d.size(); ++i) s += d[pick(random)];
    means.push_back(s / static_cast<double>(d.size()));
  }
  std::sort(means.begin(), means.end());
  c.ci_low = percentile_of_sorted(means, 0.025);
  c.ci_high = percentile_of_sorted(means, 0.975);
  c.wilcoxon_p = wilcoxon_signed_rank_p(d);
  c.sign_p = sign_test_p(c.positive, c.nonzero);
  return c;
}

}  // namespace alplan::bench
