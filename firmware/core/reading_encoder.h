// Readings as the JSON the service's POST /v1/readings accepts. One reading:
//
//   {"device":"wb-07","boot":3,"seq":42,"t_ms":1700000030000,"window_ms":30000,
//    "hr_bpm":72.4,"ibi_ms":828.7,"sdnn_ms":41.3,"rmssd_ms":35.9,"beats":36,
//    "rejected_fraction":0.028,"motion":false}
//
// on one line, keys always in this order. hr_bpm, ibi_ms and sdnn_ms are null
// when the window had fewer than the minimum accepted beats, rmssd_ms also
// when it had fewer than two successive differences; the durations have one
// decimal, rejected_fraction three. A batch is a JSON array of readings,
// "[{...},{...}]", oldest first. Both are written into a caller-given buffer
// and '\0'-terminated; the length returned excludes the terminator.
#pragma once

#include <stddef.h>

#include "reading.h"

namespace alplan::firmware {

// Enough for any reading with a valid device id, the longest numbers
// included (329 characters), with the terminator; what the reading queue
// reserves per entry.
inline constexpr size_t kMaxReadingJsonLength = 336;

enum class EncodeStatus { Ok, BufferTooSmall, InvalidDeviceId };

struct EncodeResult {
  EncodeStatus status = EncodeStatus::Ok;
  size_t length = 0;  // valid when status == Ok
};

// 1-32 characters, each a letter, digit, '.', '_' or '-'.
bool device_id_is_valid(const char* device_id);

// On failure the buffer holds an empty string (when capacity > 0).
EncodeResult encode_reading(const Reading& reading, const DeviceIdentity& device, char* buffer, size_t capacity);

// readings[0..count) as a JSON array; count 0 gives "[]".
EncodeResult encode_batch(const Reading* readings, size_t count, const DeviceIdentity& device, char* buffer,
                          size_t capacity);

}  // namespace alplan::firmware
