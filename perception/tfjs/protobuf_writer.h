// A minimal writer of the protobuf binary wire format, following the
// encoding guide (https://protobuf.dev/programming-guides/encoding/):
// varints (int32/int64/bool/enum, negatives as ten-byte two's complement),
// fixed32 floats, length-delimited bytes and nested messages, packed
// repeated scalars. It is just enough to serialise a TensorFlow GraphDef for
// OpenCV's importer without linking libprotobuf or generated code.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace alplan::perception {

class ProtobufWriter {
 public:
  // int32, int64, uint64, enum fields (proto3 omits nothing here: callers
  // decide what to write).
  void varint_field(int field, std::int64_t value);
  void bool_field(int field, bool value);
  void float_field(int field, float value);
  // string and bytes fields.
  void bytes_field(int field, std::string_view bytes);
  void message_field(int field, const ProtobufWriter& message);
  void packed_varint_field(int field, std::span<const std::int64_t> values);
  void packed_float_field(int field, std::span<const float> values);

  const std::string& bytes() const { return buffer_; }

 private:
  enum class WireType : std::uint8_t { Varint = 0, Fixed64 = 1, LengthDelimited = 2, Fixed32 = 5 };
  void tag(int field, WireType type);
  void raw_varint(std::uint64_t value);
  void raw_fixed32(std::uint32_t value);

  std::string buffer_;
};

}  // namespace alplan::perception
