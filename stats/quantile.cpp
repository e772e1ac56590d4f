#include "stats/quantile.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace alplan::stats {
namespace {

void check_share(double q) {
  if (!(q >= 0.0 && q <= 1.0)) throw std::invalid_argument("a quantile's share must be within [0, 1]");
}

}  // namespace

double nearest_rank_of_sorted(const std::vector<double>& sorted, double q) {
  check_share(q);
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  // ceil(q n) in doubles: 0.07 x 100 is 7.000000000000001, whose ceiling
  // would be rank 8; a product within 1e-9 of a whole rank is that rank.
  const double position = q * static_cast<double>(sorted.size());
  const double whole = std::round(position);
  const double rank = std::fabs(position - whole) <= 1e-9 ? whole : std::ceil(position);
  const auto index = static_cast<std::size_t>(std::max(1.0, rank)) - 1;
  return sorted[std::min(index, sorted.size() - 1)];
}

double linear_quantile_of_sorted(const std::vector<double>& sorted, double q) {
  check_share(q);
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double position = q * static_cast<double>(sorted.size() - 1);
  const auto low = static_cast<std::size_t>(std::floor(position));
  const std::size_t high = std::min(sorted.size() - 1, low + 1);
  return sorted[low] + (position - static_cast<double>(low)) * (sorted[high] - sorted[low]);
}

double nearest_rank(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return nearest_rank_of_sorted(values, q);
}

double linear_quantile(std::vector<double> values, double q) {
  std::sort(values.begin(), values.end());
  return linear_quantile_of_sorted(values, q);
}

}  // namespace alplan::stats
