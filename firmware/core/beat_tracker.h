// Which systolic peaks are beats, and the inter-beat intervals (IBIs)
// between them, with the implausible ones rejected and counted as artefacts.
//
// Intervals. An interval is rejected when it is outside [min_ibi_ms,
// max_ibi_ms] (0.3-2.0 s: 200-30 bpm), or, once median_length / 2 + 1
// intervals are known, when it differs from the running median of the
// recently accepted ones by more than max_relative_deviation (30 %). This is
// the usual "percentage filter" of HRV artefact editing (Task Force of the
// ESC and NASPE, Circulation 93(5):1043-1065, 1996). An interval too short
// means the new peak is a false one: it is dropped and the next interval is
// still measured from the last good peak. An interval too long means beats
// were missed: the chain restarts at the new peak.
//
// Amplitudes. Motion on a wrist makes peaks several times taller than the
// pulse's; a peak more than amplitude_ratio times the median amplitude of the
// recently accepted beats is rejected before its interval is looked at, and
// the chain restarts after it (its timing is not to be trusted either). The
// test is one-sided on purpose: when motion at the start teaches the median
// a motion-sized amplitude, a two-sided test would reject every true beat
// after it as too small, and nothing would ever correct it; with the
// one-sided test the true beats are accepted and bring the median back down.
// Small false peaks fail the interval tests instead.
//
// Relearning. When relearn_rejections of the last 8 intervals were rejected,
// the interval median is forgotten and learned anew: the heart rate really
// changed, or the median was learned from noise (after motion, a median of
// doubled intervals would otherwise drop every other true beat as "too
// short" for ever after; the rejected half gives it away). When no beat was
// accepted for relearn_after_ms, both medians are forgotten: the amplitude
// itself changed, e.g. a re-seated sensor.
#pragma once

#include <stdint.h>

#include "ring_buffer.h"

namespace alplan::firmware {

struct BeatTrackerConfig {
  float min_ibi_ms = 300.0f;
  float max_ibi_ms = 2000.0f;
  float max_relative_deviation = 0.3f;
  float amplitude_ratio = 2.5f;
  uint8_t median_length = 7;       // at most BeatTracker::kMaxMedianLength
  uint8_t relearn_rejections = 4;  // of the last 8 intervals, 1-8
  float relearn_after_ms = 10000.0f;
};

bool beat_tracker_config_is_valid(const BeatTrackerConfig& config);

enum class BeatKind : uint8_t {
  First,             // a peak that starts a chain: no interval yet
  Accepted,          // a plausible interval ending at this peak
  RejectedShort,     // interval too short: the peak is taken to be false and dropped
  RejectedLong,      // interval too long: beats were missed; the chain restarts here
  RejectedAmplitude, // the peak is implausibly tall; the chain restarts after it
};

struct BeatEvent {
  BeatKind kind = BeatKind::First;
  double time_ms = 0.0;  // of the peak
  float ibi_ms = 0.0f;   // the candidate interval (0 for First and RejectedAmplitude)
  // For Accepted intervals that directly follow another accepted one: this
  // interval minus the previous one, the term of RMSSD.
  bool has_successive_difference = false;
  float successive_difference_ms = 0.0f;
};

inline bool is_rejected(BeatKind kind) { return kind != BeatKind::First && kind != BeatKind::Accepted; }

class BeatTracker {
 public:
  static constexpr uint8_t kMaxMedianLength = 15;

  explicit BeatTracker(const BeatTrackerConfig& config);

  // Classifies the peak at `peak_time_ms` (non-decreasing from call to call)
  // with the band-passed signal's value `amplitude` there.
  BeatEvent on_peak(double peak_time_ms, float amplitude);

  uint32_t accepted_count() const { return accepted_count_; }
  uint32_t rejected_count() const { return rejected_count_; }

 private:
  using History = RingBuffer<float, kMaxMedianLength>;
  bool median_of(const History& history, float& median) const;
  void remember(History& history, float value);
  bool amplitude_is_implausible(float amplitude) const;
  bool interval_is_implausible(float ibi_ms, bool& too_short) const;
  bool record_interval_verdict(bool rejected);
  BeatEvent start_chain(const BeatEvent& event);
  BeatEvent accept(BeatEvent event, float amplitude);
  BeatEvent reject_interval(BeatEvent event, bool too_short);

  BeatTrackerConfig config_;
  bool has_anchor_ = false;  // a peak to measure the next interval from
  double anchor_ms_ = 0.0;
  bool previous_accepted_ = false;
  float previous_ibi_ms_ = 0.0f;
  bool has_accepted_ = false;
  double last_accepted_ms_ = 0.0;
  History recent_ibis_;
  History recent_amplitudes_;
  uint8_t recent_verdicts_ = 0;  // bit i: the i-th latest interval was rejected
  uint32_t accepted_count_ = 0;
  uint32_t rejected_count_ = 0;
};

}  // namespace alplan::firmware
