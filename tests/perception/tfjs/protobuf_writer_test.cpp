#include "perception/tfjs/protobuf_writer.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "perception/tfjs/base64.h"
#include "perception/tfjs/tfjs_weights.h"

using namespace alplan::perception;

namespace {

std::string bytes(std::initializer_list<int> values) {
  std::string out;
  for (int v : values) out.push_back(static_cast<char>(v));
  return out;
}

}  // namespace

// The expected bytes are the worked examples of the protobuf encoding guide
// (https://protobuf.dev/programming-guides/encoding/).
TEST_CASE("the protobuf writer produces the encoding guide's bytes") {
  SECTION("a varint") {
    ProtobufWriter writer;
    writer.varint_field(1, 150);
    CHECK(writer.bytes() == bytes({0x08, 0x96, 0x01}));
  }
  SECTION("a string") {
    ProtobufWriter writer;
    writer.bytes_field(2, "testing");
    CHECK(writer.bytes() == bytes({0x12, 0x07, 0x74, 0x65, 0x73, 0x74, 0x69, 0x6e, 0x67}));
  }
  SECTION("a negative int32 takes ten bytes") {
    ProtobufWriter writer;
    writer.varint_field(1, -2);
    CHECK(writer.bytes() == bytes({0x08, 0xfe, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0x01}));
  }
  SECTION("packed varints") {
    ProtobufWriter writer;
    const std::vector<std::int64_t> values = {3, 270, 86942};
    writer.packed_varint_field(4, values);
    CHECK(writer.bytes() == bytes({0x22, 0x06, 0x03, 0x8e, 0x02, 0x9e, 0xa7, 0x05}));
  }
  SECTION("a float is fixed32, little-endian") {
    ProtobufWriter writer;
    writer.float_field(4, 1.0F);
    CHECK(writer.bytes() == bytes({0x25, 0x00, 0x00, 0x80, 0x3f}));
  }
  SECTION("a nested message is length-delimited") {
    ProtobufWriter inner;
    inner.varint_field(1, 150);
    ProtobufWriter outer;
    outer.message_field(3, inner);
    CHECK(outer.bytes() == bytes({0x1a, 0x03, 0x08, 0x96, 0x01}));
  }
}

TEST_CASE("base64 decodes both alphabets, with or without padding, and rejects the rest") {
  CHECK(decode_base64("Qmlhc0FkZA==") == "BiasAdd");
  CHECK(decode_base64("Qmlhc0FkZA") == "BiasAdd");
  CHECK(decode_base64("UmVsdQ==") == "Relu");
  CHECK(decode_base64("") == "");
  CHECK(decode_base64("-_8=") == bytes({0xfb, 0xff}));
  CHECK(decode_base64("+/8=") == bytes({0xfb, 0xff}));
  CHECK_FALSE(decode_base64("Qmlhc0Fk*A==").has_value());
  CHECK_FALSE(decode_base64("Q").has_value());
}

TEST_CASE("half-precision floats widen exactly") {
  CHECK(half_to_float(0x3C00) == 1.0F);
  CHECK(half_to_float(0xC000) == -2.0F);
  CHECK(half_to_float(0x3555) == Approx(0.333251953125F).epsilon(0));
  CHECK(half_to_float(0x7BFF) == 65504.0F);
  CHECK(half_to_float(0x0001) == std::ldexp(1.0F, -24));
  CHECK(half_to_float(0x8000) == 0.0F);
  CHECK(std::signbit(half_to_float(0x8000)));
  CHECK(half_to_float(0x7C00) == std::numeric_limits<float>::infinity());
  CHECK(std::isnan(half_to_float(0x7E00)));
}
