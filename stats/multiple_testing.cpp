#include "stats/multiple_testing.h"

#include <algorithm>
#include <numeric>

namespace alplan::stats {

std::vector<double> holm_adjust(const std::vector<double>& p) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  std::vector<double> adjusted(p.size());
  double running = 0.0;  // the maximum keeps the adjusted p in the raw p's order
  for (std::size_t i = 0; i < order.size(); ++i) {
    const double multiplier = static_cast<double>(p.size() - i);
    running = std::max(running, std::min(1.0, multiplier * p[order[i]]));
    adjusted[order[i]] = running;
  }
  return adjusted;
}

std::vector<double> benjamini_hochberg_adjust(const std::vector<double>& p) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  std::vector<double> adjusted(p.size());
  // From the largest p down: the running minimum keeps the adjusted p in the
  // raw p's order.
  double running = 1.0;
  for (std::size_t i = order.size(); i-- > 0;) {
    const double m_over_rank = static_cast<double>(p.size()) / static_cast<double>(i + 1);
    running = std::min(running, std::min(1.0, m_over_rank * p[order[i]]));
    adjusted[order[i]] = running;
  }
  return adjusted;
}

}  // namespace alplan::stats
