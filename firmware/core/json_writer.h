// Bounded JSON text output into a caller's buffer: no heap, and no printf,
// whose float formatting pulls kilobytes of code (and a C library the
// embedded toolchain lacks) into the firmware. Once something does not fit,
// the writer stops writing and reports overflow; it never writes past
// `capacity`.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace alplan::firmware {

class JsonWriter {
 public:
  JsonWriter(char* buffer, size_t capacity) : buffer_(buffer), capacity_(capacity) {}

  void text(const char* literal);  // written as is: punctuation, keys
  void character(char c);
  void unsigned_integer(uint64_t value);
  // `value` rounded half away from zero to `decimals` (at most 6) places,
  // e.g. 72.25 with 1 -> "72.3"; "null" for NaN, infinities and magnitudes
  // too large for a 64-bit fixed-point (about 1e13 at 6 places).
  void fixed_point(double value, uint8_t decimals);
  void boolean(bool value);
  void null();

  bool overflowed() const { return overflowed_; }
  size_t length() const { return length_; }
  // Terminates the text with '\0' (which also needs room); false on overflow.
  bool finish();

 private:
  char* buffer_;
  size_t capacity_;
  size_t length_ = 0;
  bool overflowed_ = false;
};

}  // namespace alplan::firmware
