#include "stats/paired_comparison.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <stdexcept>
#include <tuple>

#include "stats/quantile.h"
#include "stats/rank_tests.h"

namespace alplan::stats {
namespace {

// The pairs grouped by cluster, clusters in order of first appearance (so
// that one cluster a pair reproduces the run bootstrap draw for draw).
struct Clusters {
  std::vector<double> sums;        // of the run differences
  std::vector<std::size_t> sizes;  // runs
  std::vector<double> means;       // of the differences, zero within tolerance
};

Clusters group(const std::vector<double>& d, const std::vector<std::string>& ids, const std::vector<double>& scales,
               double zero_tolerance) {
  Clusters c;
  std::vector<double> scale;
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const std::string id = ids.empty() ? std::to_string(i) : ids[i];
    const auto [it, added] = index.emplace(id, c.sums.size());
    if (added) {
      c.sums.push_back(0.0);
      c.sizes.push_back(0);
      scale.push_back(1.0);
    }
    c.sums[it->second] += d[i];
    ++c.sizes[it->second];
    scale[it->second] = std::max(scale[it->second], scales[i]);
  }
  for (std::size_t k = 0; k < c.sums.size(); ++k) {
    // Run differences of opposite sign can cancel up to rounding.
    const double mean = c.sums[k] / static_cast<double>(c.sizes[k]);
    c.means.push_back(std::fabs(mean) <= zero_tolerance * scale[k] ? 0.0 : mean);
  }
  return c;
}

// Percentile interval of the run-level mean over resampled clusters.
std::pair<double, double> cluster_bootstrap(const Clusters& c, const BootstrapOptions& options) {
  std::mt19937_64 random(options.seed);
  std::uniform_int_distribution<std::size_t> pick(0, c.sums.size() - 1);
  std::vector<double> means;
  means.reserve(static_cast<std::size_t>(std::max(options.resamples, 1)));
  for (int r = 0; r < std::max(options.resamples, 1); ++r) {
    double s = 0.0, runs = 0.0;
    for (std::size_t i = 0; i < c.sums.size(); ++i) {
      const std::size_t k = pick(random);
      s += c.sums[k];
      runs += static_cast<double>(c.sizes[k]);
    }
    means.push_back(s / runs);
  }
  std::sort(means.begin(), means.end());
  return {linear_quantile_of_sorted(means, 0.025), linear_quantile_of_sorted(means, 0.975)};
}

}  // namespace

PairedComparison compare_paired(const std::vector<double>& reference, const std::vector<double>& other,
                                const std::vector<std::string>& clusters, const BootstrapOptions& options) {
  if (reference.size() != other.size()) throw std::invalid_argument("paired samples of different sizes");
  if (!clusters.empty() && clusters.size() != reference.size())
    throw std::invalid_argument("one cluster id a pair, or none");
  PairedComparison c;
  std::vector<double> d, scales;
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    if (!std::isfinite(reference[i]) || !std::isfinite(other[i])) continue;
    // Times that went through plan text (an external planner's) differ in
    // the last digits: rounding, not a difference between strategies.
    scales.push_back(std::max({1.0, std::fabs(reference[i]), std::fabs(other[i])}));
    const double difference = other[i] - reference[i];
    d.push_back(std::fabs(difference) <= options.zero_tolerance * scales.back() ? 0.0 : difference);
    if (!clusters.empty()) ids.push_back(clusters[i]);
  }
  c.pairs = d.size();
  if (d.empty()) return c;
  for (double x : d) {
    c.nonzero += x != 0.0 ? 1 : 0;
    c.positive += x > 0.0 ? 1 : 0;
  }
  c.mean_difference = std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
  const Clusters grouped = group(d, ids, scales, options.zero_tolerance);
  c.clusters = grouped.means.size();
  for (double m : grouped.means) {
    c.nonzero_clusters += m != 0.0 ? 1 : 0;
    c.positive_clusters += m > 0.0 ? 1 : 0;
  }
  std::tie(c.ci_low, c.ci_high) = cluster_bootstrap(grouped, options);
  const SignedRank test = signed_rank_test(grouped.means, options.tie_tolerance);
  c.wilcoxon_p = test.p;
  c.wilcoxon_p_adjusted = test.p;
  c.sign_p = sign_test_p(c.positive_clusters, c.nonzero_clusters);
  c.rank_biserial = rank_biserial(test);
  c.d_z = standardized_mean_difference(grouped.means);
  return c;
}

}  // namespace alplan::stats
