// Exponential back-off with jitter, for reconnecting to Wi-Fi and re-trying
// uploads: the n-th consecutive failure waits about initial * 2^(n-1),
// capped at max, with "equal jitter" (half the delay fixed, half random) so
// that wristbands that lost the same access point do not all come back in
// the same instant (M. Brooker, "Exponential Backoff And Jitter", AWS
// Architecture Blog, 2015). The randomness is the caller's (esp_random() on
// the board), which keeps this class deterministic under test.
#pragma once

#include <stdint.h>

namespace alplan::firmware {

class RetryBackoff {
 public:
  // Preconditions: 0 < initial_ms <= max_ms.
  RetryBackoff(uint32_t initial_ms, uint32_t max_ms) : initial_ms_(initial_ms), max_ms_(max_ms) {}

  // Records a failure and returns how long to wait before the next attempt:
  // in [d/2, d] for d = min(max, initial * 2^(failures-1)), placed by
  // random_bits.
  uint32_t next_delay_ms(uint32_t random_bits);

  // After a success: the next failure waits `initial` again.
  void reset() { failures_ = 0; }
  uint32_t failures() const { return failures_; }

 private:
  uint32_t initial_ms_;
  uint32_t max_ms_;
  uint32_t failures_ = 0;
};

}  // namespace alplan::firmware
