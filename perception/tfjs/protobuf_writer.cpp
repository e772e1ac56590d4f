#include "perception/tfjs/protobuf_writer.h"

#include <bit>

namespace alplan::perception {

void ProtobufWriter::tag(int field, WireType type) {
  raw_varint((static_cast<std::uint64_t>(field) << 3U) | static_cast<std::uint64_t>(type));
}

void ProtobufWriter::raw_varint(std::uint64_t value) {
  while (value >= 0x80U) {
    buffer_.push_back(static_cast<char>((value & 0x7FU) | 0x80U));
    value >>= 7U;
  }
  buffer_.push_back(static_cast<char>(value));
}

void ProtobufWriter::raw_fixed32(std::uint32_t value) {
  // The wire format is little-endian whatever the host is.
  for (int shift = 0; shift < 32; shift += 8) buffer_.push_back(static_cast<char>((value >> shift) & 0xFFU));
}

void ProtobufWriter::varint_field(int field, std::int64_t value) {
  tag(field, WireType::Varint);
  // int32 and int64 negatives are sign-extended to 64 bits on the wire.
  raw_varint(static_cast<std::uint64_t>(value));
}

void ProtobufWriter::bool_field(int field, bool value) {
  tag(field, WireType::Varint);
  raw_varint(value ? 1 : 0);
}

void ProtobufWriter::float_field(int field, float value) {
  tag(field, WireType::Fixed32);
  raw_fixed32(std::bit_cast<std::uint32_t>(value));
}

void ProtobufWriter::bytes_field(int field, std::string_view bytes) {
  tag(field, WireType::LengthDelimited);
  raw_varint(bytes.size());
  buffer_.append(bytes);
}

void ProtobufWriter::message_field(int field, const ProtobufWriter& message) { bytes_field(field, message.bytes()); }

void ProtobufWriter::packed_varint_field(int field, std::span<const std::int64_t> values) {
  ProtobufWriter payload;
  for (std::int64_t value : values) payload.raw_varint(static_cast<std::uint64_t>(value));
  bytes_field(field, payload.bytes());
}

void ProtobufWriter::packed_float_field(int field, std::span<const float> values) {
  ProtobufWriter payload;
  for (float value : values) payload.raw_fixed32(std::bit_cast<std::uint32_t>(value));
  bytes_field(field, payload.bytes());
}

}  // namespace alplan::perception
