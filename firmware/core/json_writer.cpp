#include "json_writer.h"

#include "scalar_math.h"

namespace alplan::firmware {

void JsonWriter::character(char c) {
  if (overflowed_ || length_ >= capacity_) {
    overflowed_ = true;
    return;
  }
  buffer_[length_++] = c;
}

void JsonWriter::text(const char* literal) {
  for (const char* p = literal; *p != '\0'; ++p) character(*p);
}

void JsonWriter::unsigned_integer(uint64_t value) {
  char digits[20];
  int count = 0;
  do {
    digits[count++] = static_cast<char>('0' + value % 10);
    value /= 10;
  } while (value != 0);
  while (count > 0) character(digits[--count]);
}

void JsonWriter::fixed_point(double value, uint8_t decimals) {
  if (decimals > 6) decimals = 6;
  uint64_t scale = 1;
  for (uint8_t i = 0; i < decimals; ++i) scale *= 10;
  const bool negative = value < 0.0;
  const double magnitude = (negative ? -value : value) * static_cast<double>(scale) + 0.5;
  if (!is_finite(value) || magnitude >= 1.0e19) {
    null();
    return;
  }
  const uint64_t scaled = static_cast<uint64_t>(magnitude);
  if (negative && scaled != 0) character('-');
  unsigned_integer(scaled / scale);
  if (decimals == 0) return;
  character('.');
  uint64_t fraction = scaled % scale;
  for (uint64_t place = scale / 10; place > 0; place /= 10) {
    character(static_cast<char>('0' + fraction / place));
    fraction %= place;
  }
}

void JsonWriter::boolean(bool value) { text(value ? "true" : "false"); }

void JsonWriter::null() { text("null"); }

bool JsonWriter::finish() {
  if (overflowed_ || length_ >= capacity_) {
    overflowed_ = true;
    if (capacity_ > 0) buffer_[0] = '\0';
    return false;
  }
  buffer_[length_] = '\0';
  return true;
}

}  // namespace alplan::firmware
