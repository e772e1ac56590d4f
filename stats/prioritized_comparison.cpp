#include "stats/prioritized_comparison.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace alplan::stats {

int prioritized_score(const PrioritizedOutcome& reference, const PrioritizedOutcome& other, double tolerance) {
  if (reference.success != other.success) return other.success ? 1 : -1;
  if (!reference.success) return 0;  // both failed: nothing tells them apart
  const double scale = std::max({1.0, std::fabs(reference.value), std::fabs(other.value)});
  if (std::fabs(reference.value - other.value) <= tolerance * scale) return 0;
  return other.value < reference.value ? 1 : -1;
}

NetBenefit net_benefit(const std::vector<PrioritizedOutcome>& reference, const std::vector<PrioritizedOutcome>& other,
                       const std::vector<std::string>& clusters, const BootstrapOptions& options) {
  if (reference.size() != other.size()) throw std::invalid_argument("paired outcomes of different sizes");
  NetBenefit n;
  std::vector<double> zeros(reference.size(), 0.0), scores;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    const int s = prioritized_score(reference[i], other[i], options.zero_tolerance);
    (s > 0 ? n.wins : s < 0 ? n.losses : n.ties) += 1;
    scores.push_back(static_cast<double>(s));
  }
  n.scores = compare_paired(zeros, scores, clusters, options);
  return n;
}

}  // namespace alplan::stats
