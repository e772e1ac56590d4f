// Request latencies in bounded memory: a histogram with logarithmic buckets,
// 20 per decade from 1 microsecond to 1000 seconds, so any percentile is
// known to within about 12 % (one bucket) however many requests were timed.
// Thread-safe.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <mutex>

namespace alplan::perception::service {

class LatencyHistogram {
 public:
  static constexpr int kBucketsPerDecade = 20;
  static constexpr int kDecades = 9;  // 1e-6 .. 1e3 s
  static constexpr std::size_t kBuckets = kBucketsPerDecade * kDecades + 1;

  void record(double seconds);

  // The q-quantile (0 < q <= 1) in seconds: the upper edge of the bucket
  // that holds it; 0 before any value.
  double quantile(double q) const;
  std::uint64_t count() const;
  double sum_seconds() const;

 private:
  static std::size_t bucket_of(double seconds);
  static double upper_edge(std::size_t bucket);

  mutable std::mutex mutex_;
  std::array<std::uint64_t, kBuckets> counts_{};
  std::uint64_t total_ = 0;
  double sum_ = 0.0;
};

}  // namespace alplan::perception::service
