#include <catch2/catch.hpp>

#include <string>

#include "firmware/core/reading_encoder.h"
#include "perception/service/reading_message.h"

using namespace alplan;
using perception::service::parse_readings;
using perception::service::ReadingFormatError;

namespace {

const std::string kGood =
    R"({"device":"wb-07","boot":3,"seq":42,"t_ms":1700000030000,"window_ms":30000,"hr_bpm":72.3,"ibi_ms":830.0,)"
    R"("sdnn_ms":41.3,"rmssd_ms":35.9,"beats":36,"rejected_fraction":0.063,"motion":false})";

// kGood with `key`'s value replaced by `value` (the raw JSON text).
std::string with(const std::string& key, const std::string& value) {
  const std::string quoted = "\"" + key + "\":";
  const auto at = kGood.find(quoted) + quoted.size();
  const auto end = kGood.find_first_of(",}", at);
  return kGood.substr(0, at) + value + kGood.substr(end);
}

std::string without(const std::string& key) {
  const std::string quoted = "\"" + key + "\":";
  const auto at = kGood.find(quoted);
  const auto end = kGood.find_first_of(",}", at);
  const bool last = kGood[end] == '}';
  return last ? kGood.substr(0, at - 1) + "}" : kGood.substr(0, at) + kGood.substr(end + 1);
}

// The message of the error parse_readings throws, with its reason.
std::pair<std::string, std::string> refusal(const std::string& body, std::size_t max_batch = 12) {
  try {
    parse_readings(body, max_batch);
  } catch (const ReadingFormatError& e) {
    return {e.reason(), e.what()};
  }
  FAIL("accepted: " << body);
  return {};
}

}  // namespace

TEST_CASE("the README's reading parses into every field") {
  const auto readings = parse_readings(kGood, 12);
  REQUIRE(readings.size() == 1);
  const auto& r = readings[0];
  CHECK(r.device == "wb-07");
  CHECK(r.boot == 3);
  CHECK(r.seq == 42);
  CHECK(r.t_ms == 1700000030000ULL);
  CHECK(r.window_ms == 30000);
  CHECK(*r.hr_bpm == Approx(72.3));
  CHECK(*r.ibi_ms == Approx(830.0));
  CHECK(*r.sdnn_ms == Approx(41.3));
  CHECK(*r.rmssd_ms == Approx(35.9));
  CHECK(r.beats == 36);
  CHECK(r.rejected_fraction == Approx(0.063));
  CHECK_FALSE(r.motion);
  const firmware::WindowFeatures f = perception::service::window_features_of(r);
  CHECK(f.has_heart_rate);
  CHECK(f.has_rmssd);
  CHECK(f.mean_hr_bpm == Approx(72.3f));
  CHECK(f.beat_count == 36);
}

TEST_CASE("what the firmware encoder writes is what the service reads, single and batched") {
  firmware::Reading readings[3];
  for (uint32_t i = 0; i < 3; ++i) {
    readings[i].sequence = 10 + i;
    readings[i].timestamp_ms = 1700000000000ULL + 5000ULL * i;
    readings[i].window_ms = 30000;
    readings[i].features.beat_count = static_cast<uint16_t>(30 + i);
    readings[i].features.rejected_fraction = 0.125f;
    readings[i].features.motion_artefact = i == 2;
  }
  readings[0].features.has_heart_rate = true;
  readings[0].features.mean_hr_bpm = 64.2f;
  readings[0].features.mean_ibi_ms = 934.6f;
  readings[0].features.sdnn_ms = 52.0f;
  readings[1].features.has_heart_rate = true;  // a rate without RMSSD
  readings[1].features.mean_hr_bpm = 99.9f;
  readings[1].features.mean_ibi_ms = 600.6f;
  readings[1].features.sdnn_ms = 0.0f;
  readings[0].features.has_rmssd = true;
  readings[0].features.rmssd_ms = 20.5f;
  const firmware::DeviceIdentity device{"wb_1.A-z", 4294967295U};
  char buffer[2048];
  const auto encoded = firmware::encode_batch(readings, 3, device, buffer, sizeof buffer);
  REQUIRE(encoded.status == firmware::EncodeStatus::Ok);
  const auto parsed = parse_readings(std::string(buffer, encoded.length), 12);
  REQUIRE(parsed.size() == 3);
  CHECK(parsed[0].device == "wb_1.A-z");
  CHECK(parsed[0].boot == 4294967295U);
  CHECK(parsed[2].seq == 12);
  CHECK(*parsed[0].hr_bpm == Approx(64.2));
  CHECK(*parsed[0].rmssd_ms == Approx(20.5));
  CHECK(parsed[1].hr_bpm.has_value());
  CHECK_FALSE(parsed[1].rmssd_ms.has_value());
  CHECK_FALSE(parsed[2].hr_bpm.has_value());  // no rate: nulls
  CHECK_FALSE(parsed[2].sdnn_ms.has_value());
  CHECK(parsed[2].motion);
  CHECK(parsed[1].rejected_fraction == Approx(0.125));

  const auto single = firmware::encode_reading(readings[2], device, buffer, sizeof buffer);
  REQUIRE(single.status == firmware::EncodeStatus::Ok);
  CHECK(parse_readings(std::string(buffer, single.length), 12).at(0).seq == 12);
}

TEST_CASE("malformed JSON is refused with the parser's position") {
  for (const std::string& body : std::vector<std::string>{"", "{", "[", "not json", "{\"device\":}", kGood + ",", "[" + kGood + ",]", "\xff\xfe"}) {
    const auto [reason, message] = refusal(body);
    CHECK(reason == "malformed_json");
    CHECK(message.rfind("malformed JSON: ", 0) == 0);
  }
  CHECK(refusal("{\"a\":").second.find("line 1, column") != std::string::npos);
}

TEST_CASE("each field's type, presence and range is checked, naming the place") {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {with("device", "7"), "reading.device: expected a string, got an integer"},
      {with("device", "\"\""), "reading.device: must have 1-32 characters"},
      {with("device", "\"" + std::string(33, 'a') + "\""), "reading.device: must have 1-32 characters"},
      {with("device", "\"wb 07\""), "reading.device: may hold only letters, digits"},
      {with("device", "\"wb\\u000007\""), "reading.device: may hold only letters, digits"},
      {with("boot", "-1"), "reading.boot: must not be negative"},
      {with("boot", "4294967296"), "reading.boot: must be at most 4294967295"},
      {with("seq", "1.0"), "reading.seq: expected an integer, got a number with a fraction"},
      {with("seq", "\"42\""), "reading.seq: expected an integer, got a string"},
      {with("t_ms", "18446744073709551615"), "reading.t_ms: must be at most 9223372036854775807"},
      {with("t_ms", "null"), "reading.t_ms: expected an integer, got null"},
      {with("window_ms", "0"), "reading.window_ms: must be positive"},
      {with("window_ms", "3600001"), "reading.window_ms: must be at most 3600000"},
      {with("hr_bpm", "\"72\""), "reading.hr_bpm: expected a number or null, got a string"},
      {with("hr_bpm", "0"), "reading.hr_bpm: must be in (0.000000, 400.000000]"},
      {with("hr_bpm", "1e999"), "malformed JSON: number overflow parsing '1e999'"},
      {with("ibi_ms", "-5"), "reading.ibi_ms: must be in (0.000000"},
      {with("sdnn_ms", "[]"), "reading.sdnn_ms: expected a number or null, got an array"},
      {with("rmssd_ms", "-0.1"), "reading.rmssd_ms: must be in [0.000000"},
      {with("beats", "65536"), "reading.beats: must be at most 65535"},
      {with("rejected_fraction", "1.5"), "reading.rejected_fraction: must be in [0.000000, 1.000000]"},
      {with("rejected_fraction", "null"), "reading.rejected_fraction: expected a number, got null"},
      {with("motion", "0"), "reading.motion: expected a boolean, got an integer"},
      {with("hr_bpm", "null"), "reading: hr_bpm, ibi_ms and sdnn_ms must be null together"},
      {without("seq"), "reading: missing key 'seq'"},
      {without("motion"), "reading: missing key 'motion'"},
      {kGood.substr(0, kGood.size() - 1) + ",\"extra\":1}", "reading: unknown key 'extra'"},
      {"7", "body: expected a reading object or an array of readings, got an integer"},
      {"\"hello\"", "body: expected a reading object or an array of readings, got a string"},
      {"[]", "body: the array holds no readings"},
      {"[" + kGood + ",5]", "readings[1]: expected an object, got an integer"},
      {"[" + kGood + "," + with("seq", "-3") + "]", "readings[1].seq: must not be negative"},
  };
  for (const auto& [body, expected] : cases) {
    INFO(body);
    const auto [reason, message] = refusal(body);
    CHECK(message.find(expected) != std::string::npos);
    CHECK(reason == (expected.rfind("malformed JSON", 0) == 0 ? "malformed_json" : "invalid_reading"));
  }
}

TEST_CASE("a batch holds at most max_batch readings") {
  std::string twelve = "[";
  for (int i = 0; i < 12; ++i) twelve += (i ? "," : "") + with("seq", std::to_string(i));
  CHECK(parse_readings(twelve + "]", 12).size() == 12);
  CHECK(refusal(twelve + "," + kGood + "]").second == "body: a batch holds at most 12 readings, this one 13");
  CHECK(refusal(twelve + "]", 5).second == "body: a batch holds at most 5 readings, this one 12");
}
