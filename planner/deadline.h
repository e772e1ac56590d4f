// A moment after which a long computation (grounding) gives up. Checking it
// must cost next to nothing inside tight loops, so the clock is read only
// once every `stride` checks; between readings a check is a counter
// increment. Each loop owns its copy (the counter is per copy): no shared
// or global state.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace alplan {

// Thrown when grounding runs past its deadline. Not a GroundingError: the
// input is fine, the limit was too tight.
class GroundingTimeout : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;

  Deadline() = default;  // never passes
  explicit Deadline(std::optional<Clock::time_point> at, std::uint32_t stride = 256) : at_(at), stride_(stride) {}

  // True once the moment has passed (read on every `stride`-th call).
  bool passed() {
    if (!at_ || ++calls_ < stride_) return false;
    calls_ = 0;
    return Clock::now() > *at_;
  }
  // Throws GroundingTimeout naming `where` once the moment has passed.
  void check(const char* where) {
    if (passed()) throw GroundingTimeout(std::string("the time limit was reached while grounding (") + where + ")");
  }

 private:
  std::optional<Clock::time_point> at_;
  std::uint32_t stride_ = 256;
  std::uint32_t calls_ = 0;
};

}  // namespace alplan
