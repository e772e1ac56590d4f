#include <catch2/catch.hpp>

#include <cstring>
#include <limits>
#include <string>

#include "firmware/core/json_writer.h"
#include "firmware/core/reading_encoder.h"

using namespace alplan::firmware;

namespace {

std::string fixed(double value, uint8_t decimals) {
  char buffer[64];
  JsonWriter out(buffer, sizeof buffer);
  out.fixed_point(value, decimals);
  REQUIRE(out.finish());
  return buffer;
}

Reading example_reading() {
  Reading reading;
  reading.sequence = 42;
  reading.timestamp_ms = 1700000030000ULL;
  reading.window_ms = 30000;
  WindowFeatures& f = reading.features;
  f.has_heart_rate = true;
  f.has_rmssd = true;
  f.mean_hr_bpm = 72.25f;  // exactly representable: rounds half away from zero
  f.mean_ibi_ms = 830.0f;
  f.sdnn_ms = 41.3f;
  f.rmssd_ms = 35.875f;
  f.beat_count = 36;
  f.rejected_fraction = 0.0625f;
  f.motion_artefact = false;
  return reading;
}

const char* const kExampleJson =
    "{\"device\":\"wb-07\",\"boot\":3,\"seq\":42,\"t_ms\":1700000030000,\"window_ms\":30000,"
    "\"hr_bpm\":72.3,\"ibi_ms\":830.0,\"sdnn_ms\":41.3,\"rmssd_ms\":35.9,\"beats\":36,"
    "\"rejected_fraction\":0.063,\"motion\":false}";

}  // namespace

TEST_CASE("fixed-point numbers are rounded half away from zero without printf") {
  CHECK(fixed(72.25, 1) == "72.3");
  CHECK(fixed(-72.25, 1) == "-72.3");
  CHECK(fixed(0.0, 2) == "0.00");
  CHECK(fixed(-0.04, 1) == "0.0");  // no negative zero
  CHECK(fixed(1.005, 0) == "1");
  CHECK(fixed(0.0625, 3) == "0.063");
  CHECK(fixed(123456.789, 6) == "123456.789000");
  CHECK(fixed(2.5e-7, 6) == "0.000000");
  CHECK(fixed(std::numeric_limits<double>::quiet_NaN(), 1) == "null");
  CHECK(fixed(std::numeric_limits<double>::infinity(), 1) == "null");
  CHECK(fixed(-std::numeric_limits<double>::infinity(), 1) == "null");
  CHECK(fixed(1.0e20, 1) == "null");
}

TEST_CASE("the writer never writes past its buffer and reports overflow") {
  char buffer[8];
  std::memset(buffer, 'x', sizeof buffer);
  JsonWriter out(buffer, 5);
  out.text("abcdef");
  CHECK(out.overflowed());
  CHECK_FALSE(out.finish());
  CHECK(buffer[5] == 'x');
  CHECK(buffer[0] == '\0');

  JsonWriter exact(buffer, 4);
  exact.unsigned_integer(123);
  CHECK(exact.finish());
  CHECK(std::string(buffer) == "123");
}

TEST_CASE("a reading is encoded as exactly the documented JSON") {
  char buffer[kMaxReadingJsonLength];
  const EncodeResult result = encode_reading(example_reading(), {"wb-07", 3}, buffer, sizeof buffer);
  REQUIRE(result.status == EncodeStatus::Ok);
  CHECK(std::string(buffer) == kExampleJson);
  CHECK(result.length == std::strlen(kExampleJson));
}

TEST_CASE("missing rates are null") {
  Reading reading = example_reading();
  reading.features.has_heart_rate = false;
  reading.features.has_rmssd = false;
  reading.features.beat_count = 2;
  reading.features.motion_artefact = true;
  char buffer[kMaxReadingJsonLength];
  REQUIRE(encode_reading(reading, {"wb-07", 3}, buffer, sizeof buffer).status == EncodeStatus::Ok);
  CHECK(std::string(buffer) ==
        "{\"device\":\"wb-07\",\"boot\":3,\"seq\":42,\"t_ms\":1700000030000,\"window_ms\":30000,"
        "\"hr_bpm\":null,\"ibi_ms\":null,\"sdnn_ms\":null,\"rmssd_ms\":null,\"beats\":2,"
        "\"rejected_fraction\":0.063,\"motion\":true}");
}

TEST_CASE("a buffer too small is an error, at every size short of the reading") {
  const std::size_t needed = std::strlen(kExampleJson) + 1;
  char buffer[kMaxReadingJsonLength];
  for (std::size_t capacity = 0; capacity < needed; ++capacity) {
    const EncodeResult result = encode_reading(example_reading(), {"wb-07", 3}, buffer, capacity);
    CHECK(result.status == EncodeStatus::BufferTooSmall);
    CHECK(result.length == 0);
  }
  CHECK(encode_reading(example_reading(), {"wb-07", 3}, buffer, needed).status == EncodeStatus::Ok);
}

TEST_CASE("device ids are restricted so that they need no escaping") {
  CHECK(device_id_is_valid("wb-07"));
  CHECK(device_id_is_valid("A.b_c-9"));
  CHECK(device_id_is_valid("abcdefghijabcdefghijabcdefghij12"));  // 32
  CHECK_FALSE(device_id_is_valid("abcdefghijabcdefghijabcdefghij123"));  // 33
  CHECK_FALSE(device_id_is_valid(""));
  CHECK_FALSE(device_id_is_valid(nullptr));
  CHECK_FALSE(device_id_is_valid("wb\"07"));
  CHECK_FALSE(device_id_is_valid("wb 07"));
  char buffer[kMaxReadingJsonLength];
  CHECK(encode_reading(example_reading(), {"bad id", 1}, buffer, sizeof buffer).status ==
        EncodeStatus::InvalidDeviceId);
  CHECK(std::string(buffer).empty());
}

TEST_CASE("the longest possible reading fits the queue's entry size") {
  Reading reading;
  reading.sequence = std::numeric_limits<uint32_t>::max();
  reading.timestamp_ms = std::numeric_limits<uint64_t>::max();
  reading.window_ms = std::numeric_limits<uint32_t>::max();
  WindowFeatures& f = reading.features;
  f.has_heart_rate = f.has_rmssd = true;
  f.mean_hr_bpm = f.mean_ibi_ms = f.sdnn_ms = f.rmssd_ms = -9.9e17f;  // the widest non-null
  f.rejected_fraction = -9.9e15f;
  f.beat_count = std::numeric_limits<uint16_t>::max();
  f.motion_artefact = false;
  char buffer[kMaxReadingJsonLength];
  const EncodeResult result =
      encode_reading(reading, {"abcdefghijabcdefghijabcdefghij12", std::numeric_limits<uint32_t>::max()}, buffer,
                     sizeof buffer);
  REQUIRE(result.status == EncodeStatus::Ok);
  CHECK(std::string(buffer).find("null") == std::string::npos);
  CHECK(result.length < kMaxReadingJsonLength);
}

TEST_CASE("a batch is a JSON array of readings") {
  Reading readings[2] = {example_reading(), example_reading()};
  readings[1].sequence = 43;
  char buffer[2 * kMaxReadingJsonLength];
  const EncodeResult result = encode_batch(readings, 2, {"wb-07", 3}, buffer, sizeof buffer);
  REQUIRE(result.status == EncodeStatus::Ok);
  std::string second = kExampleJson;
  second.replace(second.find("\"seq\":42"), 8, "\"seq\":43");
  CHECK(std::string(buffer) == "[" + std::string(kExampleJson) + "," + second + "]");

  CHECK(encode_batch(readings, 0, {"wb-07", 3}, buffer, sizeof buffer).length == 2);
  CHECK(std::string(buffer) == "[]");
  CHECK(encode_batch(readings, 2, {"wb-07", 3}, buffer, result.length).status == EncodeStatus::BufferTooSmall);
}
