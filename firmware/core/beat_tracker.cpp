#include "beat_tracker.h"

#include "order_statistics.h"
#include "scalar_math.h"

namespace alplan::firmware {

bool beat_tracker_config_is_valid(const BeatTrackerConfig& config) {
  return config.min_ibi_ms > 0.0f && config.min_ibi_ms < config.max_ibi_ms && config.max_relative_deviation > 0.0f &&
         config.max_relative_deviation < 1.0f && config.amplitude_ratio > 1.0f && config.median_length >= 1 &&
         config.median_length <= BeatTracker::kMaxMedianLength && config.relearn_rejections >= 1 &&
         config.relearn_rejections <= 8 && config.relearn_after_ms > config.max_ibi_ms;
}

BeatTracker::BeatTracker(const BeatTrackerConfig& config) : config_(config) {}

bool BeatTracker::median_of(const History& history, float& median) const {
  if (history.size() < config_.median_length / 2u + 1u) return false;
  float scratch[kMaxMedianLength];
  for (size_t i = 0; i < history.size(); ++i) scratch[i] = history[i];
  median = median_in_place(scratch, history.size());
  return true;
}

void BeatTracker::remember(History& history, float value) {
  if (history.size() >= config_.median_length) history.pop_front();
  history.push_back(value);
}

bool BeatTracker::amplitude_is_implausible(float amplitude) const {
  float median = 0.0f;
  if (!median_of(recent_amplitudes_, median)) return false;
  return amplitude > config_.amplitude_ratio * median;
}

bool BeatTracker::interval_is_implausible(float ibi_ms, bool& too_short) const {
  too_short = ibi_ms < config_.min_ibi_ms;
  if (too_short || ibi_ms > config_.max_ibi_ms) return true;
  float median = 0.0f;
  if (!median_of(recent_ibis_, median)) return false;
  too_short = ibi_ms < median;
  return absolute(ibi_ms - median) > config_.max_relative_deviation * median;
}

// Records one interval's verdict; true when the interval median should be
// relearned.
bool BeatTracker::record_interval_verdict(bool rejected) {
  recent_verdicts_ = static_cast<uint8_t>((static_cast<unsigned>(recent_verdicts_) << 1u) | (rejected ? 1u : 0u));
  uint8_t rejections = 0;
  for (uint8_t bits = recent_verdicts_; bits != 0; bits = static_cast<uint8_t>(bits & (bits - 1))) ++rejections;
  if (rejections < config_.relearn_rejections) return false;
  recent_verdicts_ = 0;
  return true;
}

BeatEvent BeatTracker::start_chain(const BeatEvent& event) {
  has_anchor_ = true;
  anchor_ms_ = event.time_ms;
  previous_accepted_ = false;
  return event;
}

BeatEvent BeatTracker::accept(BeatEvent event, float amplitude) {
  event.kind = BeatKind::Accepted;
  if (previous_accepted_) {
    event.has_successive_difference = true;
    event.successive_difference_ms = event.ibi_ms - previous_ibi_ms_;
  }
  previous_accepted_ = true;
  previous_ibi_ms_ = event.ibi_ms;
  anchor_ms_ = event.time_ms;
  has_accepted_ = true;
  last_accepted_ms_ = event.time_ms;
  record_interval_verdict(false);
  remember(recent_ibis_, event.ibi_ms);
  remember(recent_amplitudes_, amplitude);
  ++accepted_count_;
  return event;
}

BeatEvent BeatTracker::reject_interval(BeatEvent event, bool too_short) {
  ++rejected_count_;
  if (too_short) {
    event.kind = BeatKind::RejectedShort;
  } else {
    event.kind = BeatKind::RejectedLong;
    anchor_ms_ = event.time_ms;
    previous_accepted_ = false;
  }
  if (record_interval_verdict(true)) {
    recent_ibis_.clear();
    anchor_ms_ = event.time_ms;
    previous_accepted_ = false;
  }
  return event;
}

BeatEvent BeatTracker::on_peak(double peak_time_ms, float amplitude) {
  BeatEvent event;
  event.time_ms = peak_time_ms;
  const double since_accepted = has_accepted_ ? peak_time_ms - last_accepted_ms_ : 0.0;
  if (since_accepted > static_cast<double>(config_.relearn_after_ms)) {
    recent_ibis_.clear();
    recent_amplitudes_.clear();
    recent_verdicts_ = 0;
    has_accepted_ = false;
    has_anchor_ = false;
  }
  if (amplitude_is_implausible(amplitude)) {
    ++rejected_count_;
    event.kind = BeatKind::RejectedAmplitude;
    has_anchor_ = false;
    previous_accepted_ = false;
    return event;
  }
  if (!has_anchor_) return start_chain(event);
  event.ibi_ms = static_cast<float>(peak_time_ms - anchor_ms_);
  bool too_short = false;
  if (interval_is_implausible(event.ibi_ms, too_short)) return reject_interval(event, too_short);
  return accept(event, amplitude);
}

}  // namespace alplan::firmware
