// The body of POST /v1/readings, read and checked: exactly the JSON the
// wristband's encoder writes (firmware/core/reading_encoder.h, documented in
// firmware/README.md), one reading as an object or a batch as an array of
// 1..max_batch objects, oldest first.
//
// Validation is strict because the only legitimate writer is our own
// encoder: every key must be present with its type and range, unknown keys
// are refused, integers must be JSON integers (42, not 42.0), and hr_bpm,
// ibi_ms and sdnn_ms are null together. A body that fails here would never be
// accepted, so it is answered with 400 (the board then drops it rather than
// retrying forever, see firmware/core/upload_policy.h); the message names the
// place: "readings[3].hr_bpm: expected a number or null, got a string".
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "firmware/core/window_features.h"

namespace alplan::perception::service {

struct ReceivedReading {
  std::string device;
  std::uint32_t boot = 0;
  std::uint32_t seq = 0;
  std::uint64_t t_ms = 0;
  std::uint32_t window_ms = 0;
  std::optional<double> hr_bpm, ibi_ms, sdnn_ms, rmssd_ms;
  std::uint32_t beats = 0;
  double rejected_fraction = 0.0;
  bool motion = false;
};

// The stress detector's view of a reading (firmware::WindowFeatures).
firmware::WindowFeatures window_features_of(const ReceivedReading& reading);

// The body could not be read as readings. `reason` is short and stable (a
// metrics label): "malformed_json" or "invalid_reading".
class ReadingFormatError : public std::runtime_error {
 public:
  ReadingFormatError(std::string reason, const std::string& message)
      : std::runtime_error(message), reason_(std::move(reason)) {}
  const std::string& reason() const { return reason_; }

 private:
  std::string reason_;
};

// Throws ReadingFormatError. The places in messages are "reading" for a
// single object and "readings[i]" inside an array.
std::vector<ReceivedReading> parse_readings(std::string_view body, std::size_t max_batch);

// The largest t_ms accepted: SQLite keeps integers as int64.
inline constexpr std::uint64_t kMaxTimestampMs = 9223372036854775807ULL;
inline constexpr std::uint32_t kMaxWindowMs = 3600000;  // an hour; the core allows 5-60 s

}  // namespace alplan::perception::service
