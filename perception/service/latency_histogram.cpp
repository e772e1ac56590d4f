#include "perception/service/latency_histogram.h"

#include <cmath>

namespace alplan::perception::service {

std::size_t LatencyHistogram::bucket_of(double seconds) {
  if (!(seconds > 1e-6)) return 0;
  const double position = (std::log10(seconds) + 6.0) * kBucketsPerDecade;
  const double bucket = std::ceil(position - 1e-9);
  if (bucket >= static_cast<double>(kBuckets - 1)) return kBuckets - 1;
  return static_cast<std::size_t>(bucket);
}

double LatencyHistogram::upper_edge(std::size_t bucket) {
  return std::pow(10.0, static_cast<double>(bucket) / kBucketsPerDecade - 6.0);
}

void LatencyHistogram::record(double seconds) {
  const std::size_t bucket = bucket_of(seconds);
  const std::lock_guard lock(mutex_);
  counts_[bucket] += 1;
  total_ += 1;
  sum_ += seconds > 0.0 ? seconds : 0.0;
}

double LatencyHistogram::quantile(double q) const {
  const std::lock_guard lock(mutex_);
  if (total_ == 0) return 0.0;
  // The smallest bucket whose cumulative count reaches ceil(q * total).
  const auto rank = static_cast<std::uint64_t>(std::ceil(q * static_cast<double>(total_)));
  std::uint64_t seen = 0;
  for (std::size_t b = 0; b < kBuckets; ++b) {
    seen += counts_[b];
    if (seen >= rank && seen > 0) return upper_edge(b);
  }
  return upper_edge(kBuckets - 1);
}

std::uint64_t LatencyHistogram::count() const {
  const std::lock_guard lock(mutex_);
  return total_;
}

double LatencyHistogram::sum_seconds() const {
  const std::lock_guard lock(mutex_);
  return sum_;
}

}  // namespace alplan::perception::service
