#include "retry_backoff.h"

namespace alplan::firmware {

uint32_t RetryBackoff::next_delay_ms(uint32_t random_bits) {
  uint64_t delay = initial_ms_;
  for (uint32_t i = 0; i < failures_ && delay < max_ms_; ++i) delay *= 2;
  if (delay > max_ms_) delay = max_ms_;
  if (failures_ < UINT32_MAX) ++failures_;
  const uint64_t half = delay / 2;
  return static_cast<uint32_t>(delay - half + random_bits % (half + 1));
}

}  // namespace alplan::firmware
