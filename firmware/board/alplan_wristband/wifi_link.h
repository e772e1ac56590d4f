// Keeps the station connected: connects, notices a lost connection, and
// reconnects with exponential back-off (firmware/core/retry_backoff.h) so
// that a wristband out of range does not hammer the access point or drain
// its battery. Also sets the clock from NTP once connected: readings carry
// Unix milliseconds.
#pragma once

#include <stdint.h>

#include "retry_backoff.h"

namespace alplan::board {

class WifiLink {
 public:
  WifiLink();

  // Call often (every loop); never blocks for long.
  void poll(uint32_t now_ms);

  bool connected() const;
  // True once NTP has set the clock (it stays set through Wi-Fi outages).
  bool clock_set() const;
  // Milliseconds since the Unix epoch, from the system clock.
  static uint64_t unix_time_ms();

 private:
  void start_attempt(uint32_t now_ms);

  firmware::RetryBackoff backoff_;
  bool attempting_ = false;
  bool was_connected_ = false;
  bool ntp_started_ = false;
  uint32_t attempt_started_ms_ = 0;
  uint32_t next_attempt_ms_ = 0;
};

}  // namespace alplan::board
