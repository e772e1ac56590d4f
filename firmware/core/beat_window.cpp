#include "beat_window.h"

#include "scalar_math.h"

namespace alplan::firmware {

void BeatWindow::add(const BeatEvent& event) {
  if (event.kind == BeatKind::First) return;
  events_.push_back_overwrite(event);
}

BeatStatistics BeatWindow::statistics(double start_ms, double end_ms) const {
  BeatStatistics result;
  double ibi_sum = 0.0;
  double squared_difference_sum = 0.0;
  bool accepted_seen = false;
  for (size_t i = 0; i < events_.size(); ++i) {
    const BeatEvent& event = events_[i];
    if (event.time_ms <= start_ms || event.time_ms > end_ms) continue;
    if (is_rejected(event.kind)) {
      ++result.rejected;
      continue;
    }
    ++result.accepted;
    ibi_sum += static_cast<double>(event.ibi_ms);
    if (event.has_successive_difference && accepted_seen) {
      ++result.successive_differences;
      const double difference = static_cast<double>(event.successive_difference_ms);
      squared_difference_sum += difference * difference;
    }
    accepted_seen = true;
  }
  if (result.accepted == 0) return result;
  const double mean = ibi_sum / result.accepted;
  result.mean_ibi_ms = static_cast<float>(mean);
  if (result.accepted >= 2) {
    // Second pass around the mean: the one-pass formula cancels badly when
    // the spread is small against the mean, as it is for IBIs.
    double squared_deviation_sum = 0.0;
    for (size_t i = 0; i < events_.size(); ++i) {
      const BeatEvent& event = events_[i];
      if (event.time_ms <= start_ms || event.time_ms > end_ms || event.kind != BeatKind::Accepted) continue;
      const double deviation = static_cast<double>(event.ibi_ms) - mean;
      squared_deviation_sum += deviation * deviation;
    }
    result.sdnn_ms = static_cast<float>(square_root(squared_deviation_sum / (result.accepted - 1)));
  }
  if (result.successive_differences > 0) {
    result.rmssd_ms = static_cast<float>(square_root(squared_difference_sum / result.successive_differences));
  }
  return result;
}

}  // namespace alplan::firmware
