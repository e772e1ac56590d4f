// The recent beat events, and their time-domain statistics over a window:
// mean IBI, SDNN and RMSSD as defined by the Task Force of the ESC and NASPE
// (Circulation 93(5):1043-1065, 1996), over the accepted intervals only.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "beat_tracker.h"
#include "ring_buffer.h"

namespace alplan::firmware {

struct BeatStatistics {
  uint16_t accepted = 0;                // accepted intervals ending in the window
  uint16_t rejected = 0;                // rejected intervals ending in the window
  uint16_t successive_differences = 0;  // pairs of adjacent accepted intervals
  float mean_ibi_ms = 0.0f;             // 0 without accepted intervals
  float sdnn_ms = 0.0f;                 // sample standard deviation; 0 under two intervals
  float rmssd_ms = 0.0f;                // 0 without successive differences
};

class BeatWindow {
 public:
  // Room for 60 s of events at 200 bpm with some false peaks besides; when a
  // window holds more, its oldest events are the ones forgotten.
  static constexpr size_t kCapacity = 256;

  // Keeps accepted and rejected events; First events carry no interval.
  void add(const BeatEvent& event);

  // Statistics of the events whose peak time is in (start_ms, end_ms]. A
  // successive difference counts when both its intervals are in the window.
  BeatStatistics statistics(double start_ms, double end_ms) const;

 private:
  RingBuffer<BeatEvent, kCapacity> events_;
};

}  // namespace alplan::firmware
