#include "perception/service/reading_message.h"

#include <array>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

namespace alplan::perception::service {
namespace {

using nlohmann::json;

constexpr std::array<const char*, 12> kKeys = {"device", "boot",     "seq",   "t_ms",  "window_ms",         "hr_bpm",
                                               "ibi_ms", "sdnn_ms", "rmssd_ms", "beats", "rejected_fraction", "motion"};
constexpr std::size_t kMaxDeviceIdLength = 32;

const char* type_name(const json& value) {
  switch (value.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return "a boolean";
    case json::value_t::string: return "a string";
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return "an integer";
    case json::value_t::number_float: return "a number with a fraction";
    default: return "something else";
  }
}

[[noreturn]] void invalid(const std::string& place, const std::string& problem) {
  throw ReadingFormatError("invalid_reading", place + ": " + problem);
}

// A reading read out of one JSON object; `place` prefixes every message.
class ReadingReader {
 public:
  ReadingReader(const json& object, std::string place) : object_(object), place_(std::move(place)) {}

  ReceivedReading read() const {
    if (!object_.is_object()) invalid(place_, std::string("expected an object, got ") + type_name(object_));
    for (const auto& item : object_.items()) {
      bool known = false;
      for (const char* key : kKeys) known = known || item.key() == key;
      if (!known) invalid(place_, "unknown key '" + printable(item.key()) + "'");
    }
    ReceivedReading r;
    r.device = device();
    r.boot = unsigned_integer<std::uint32_t>("boot", std::numeric_limits<std::uint32_t>::max());
    r.seq = unsigned_integer<std::uint32_t>("seq", std::numeric_limits<std::uint32_t>::max());
    r.t_ms = unsigned_integer<std::uint64_t>("t_ms", kMaxTimestampMs);
    r.window_ms = unsigned_integer<std::uint32_t>("window_ms", kMaxWindowMs);
    if (r.window_ms == 0) invalid(field("window_ms"), "must be positive");
    r.hr_bpm = number_or_null("hr_bpm", 0.0, 400.0, false);
    r.ibi_ms = number_or_null("ibi_ms", 0.0, 60000.0, false);
    r.sdnn_ms = number_or_null("sdnn_ms", 0.0, 60000.0, true);
    r.rmssd_ms = number_or_null("rmssd_ms", 0.0, 60000.0, true);
    if (r.hr_bpm.has_value() != r.ibi_ms.has_value() || r.hr_bpm.has_value() != r.sdnn_ms.has_value()) {
      invalid(place_, "hr_bpm, ibi_ms and sdnn_ms must be null together");
    }
    r.beats = unsigned_integer<std::uint32_t>("beats", std::numeric_limits<std::uint16_t>::max());
    const std::optional<double> rejected = number_or_null("rejected_fraction", 0.0, 1.0, true);
    if (!rejected) invalid(field("rejected_fraction"), "expected a number, got null");
    r.rejected_fraction = *rejected;
    const json& motion = value("motion");
    if (!motion.is_boolean()) invalid(field("motion"), std::string("expected a boolean, got ") + type_name(motion));
    r.motion = motion.get<bool>();
    return r;
  }

 private:
  std::string field(const char* key) const { return place_ + "." + key; }

  // Keys are echoed in messages; keep them short and printable.
  static std::string printable(const std::string& text) {
    std::string out;
    for (const char c : text.substr(0, 40)) out += (c >= 0x20 && c < 0x7f && c != '\'') ? c : '?';
    return text.size() > 40 ? out + "..." : out;
  }

  const json& value(const char* key) const {
    const auto it = object_.find(key);
    if (it == object_.end()) invalid(place_, std::string("missing key '") + key + "'");
    return *it;
  }

  std::string device() const {
    const json& v = value("device");
    if (!v.is_string()) invalid(field("device"), std::string("expected a string, got ") + type_name(v));
    const std::string& id = v.get_ref<const std::string&>();
    if (id.empty() || id.size() > kMaxDeviceIdLength) invalid(field("device"), "must have 1-32 characters");
    for (const char c : id) {
      const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' ||
                      c == '_' || c == '-';
      if (!ok) invalid(field("device"), "may hold only letters, digits, '.', '_' and '-'");
    }
    return id;
  }

  template <typename Integer>
  Integer unsigned_integer(const char* key, std::uint64_t max) const {
    const json& v = value(key);
    if (v.is_number_integer() && !v.is_number_unsigned()) invalid(field(key), "must not be negative");
    if (!v.is_number_unsigned()) invalid(field(key), std::string("expected an integer, got ") + type_name(v));
    const std::uint64_t n = v.get<std::uint64_t>();
    if (n > max) invalid(field(key), "must be at most " + std::to_string(max));
    return static_cast<Integer>(n);
  }

  std::optional<double> number_or_null(const char* key, double low, double high, bool low_inclusive) const {
    const json& v = value(key);
    if (v.is_null()) return std::nullopt;
    if (!v.is_number()) invalid(field(key), std::string("expected a number or null, got ") + type_name(v));
    const double x = v.get<double>();
    const bool above_low = low_inclusive ? x >= low : x > low;
    if (!std::isfinite(x) || !above_low || x > high) {
      invalid(field(key), std::string("must be in ") + (low_inclusive ? "[" : "(") + std::to_string(low) + ", " +
                              std::to_string(high) + "]");
    }
    return x;
  }

  const json& object_;
  std::string place_;
};

}  // namespace

firmware::WindowFeatures window_features_of(const ReceivedReading& reading) {
  firmware::WindowFeatures f;
  f.has_heart_rate = reading.hr_bpm.has_value();
  f.has_rmssd = reading.rmssd_ms.has_value();
  f.mean_hr_bpm = static_cast<float>(reading.hr_bpm.value_or(0.0));
  f.mean_ibi_ms = static_cast<float>(reading.ibi_ms.value_or(0.0));
  f.sdnn_ms = static_cast<float>(reading.sdnn_ms.value_or(0.0));
  f.rmssd_ms = static_cast<float>(reading.rmssd_ms.value_or(0.0));
  f.beat_count = static_cast<std::uint16_t>(reading.beats);
  f.rejected_fraction = static_cast<float>(reading.rejected_fraction);
  f.motion_artefact = reading.motion;
  return f;
}

std::vector<ReceivedReading> parse_readings(std::string_view body, std::size_t max_batch) {
  json document;
  try {
    document = json::parse(body);
  } catch (const json::exception& e) {
    // A syntax error (parse_error) or a number beyond double (out_of_range);
    // nlohmann's message: "[json.exception.parse_error.101] parse error at line 1, column 3: ..."
    std::string message = e.what();
    if (const auto at = message.find("] "); at != std::string::npos) message.erase(0, at + 2);
    throw ReadingFormatError("malformed_json", "malformed JSON: " + message);
  }
  std::vector<ReceivedReading> readings;
  if (document.is_object()) {
    readings.push_back(ReadingReader(document, "reading").read());
    return readings;
  }
  if (!document.is_array()) {
    invalid("body", std::string("expected a reading object or an array of readings, got ") + type_name(document));
  }
  if (document.empty()) invalid("body", "the array holds no readings");
  if (document.size() > max_batch) {
    invalid("body", "a batch holds at most " + std::to_string(max_batch) + " readings, this one " +
                        std::to_string(document.size()));
  }
  readings.reserve(document.size());
  for (std::size_t i = 0; i < document.size(); ++i) {
    readings.push_back(ReadingReader(document[i], "readings[" + std::to_string(i) + "]").read());
  }
  return readings;
}

}  // namespace alplan::perception::service
