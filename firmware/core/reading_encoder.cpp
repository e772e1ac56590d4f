#include "reading_encoder.h"

#include "json_writer.h"

namespace alplan::firmware {

namespace {

constexpr size_t kMaxDeviceIdLength = 32;

bool is_device_id_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
         c == '-';
}

void write_optional(JsonWriter& out, bool present, float value, uint8_t decimals) {
  if (present) {
    out.fixed_point(static_cast<double>(value), decimals);
  } else {
    out.null();
  }
}

void write_reading(JsonWriter& out, const Reading& reading, const DeviceIdentity& device) {
  const WindowFeatures& f = reading.features;
  out.text("{\"device\":\"");
  out.text(device.device_id);
  out.text("\",\"boot\":");
  out.unsigned_integer(device.boot);
  out.text(",\"seq\":");
  out.unsigned_integer(reading.sequence);
  out.text(",\"t_ms\":");
  out.unsigned_integer(reading.timestamp_ms);
  out.text(",\"window_ms\":");
  out.unsigned_integer(reading.window_ms);
  out.text(",\"hr_bpm\":");
  write_optional(out, f.has_heart_rate, f.mean_hr_bpm, 1);
  out.text(",\"ibi_ms\":");
  write_optional(out, f.has_heart_rate, f.mean_ibi_ms, 1);
  out.text(",\"sdnn_ms\":");
  write_optional(out, f.has_heart_rate, f.sdnn_ms, 1);
  out.text(",\"rmssd_ms\":");
  write_optional(out, f.has_rmssd, f.rmssd_ms, 1);
  out.text(",\"beats\":");
  out.unsigned_integer(f.beat_count);
  out.text(",\"rejected_fraction\":");
  out.fixed_point(static_cast<double>(f.rejected_fraction), 3);
  out.text(",\"motion\":");
  out.boolean(f.motion_artefact);
  out.character('}');
}

EncodeResult finish(JsonWriter& out) {
  if (!out.finish()) return {EncodeStatus::BufferTooSmall, 0};
  return {EncodeStatus::Ok, out.length()};
}

EncodeResult invalid_device(char* buffer, size_t capacity) {
  if (capacity > 0) buffer[0] = '\0';
  return {EncodeStatus::InvalidDeviceId, 0};
}

}  // namespace

bool device_id_is_valid(const char* device_id) {
  if (device_id == nullptr) return false;
  size_t length = 0;
  for (; device_id[length] != '\0'; ++length) {
    if (length >= kMaxDeviceIdLength || !is_device_id_character(device_id[length])) return false;
  }
  return length > 0;
}

EncodeResult encode_reading(const Reading& reading, const DeviceIdentity& device, char* buffer, size_t capacity) {
  if (!device_id_is_valid(device.device_id)) return invalid_device(buffer, capacity);
  JsonWriter out(buffer, capacity);
  write_reading(out, reading, device);
  return finish(out);
}

EncodeResult encode_batch(const Reading* readings, size_t count, const DeviceIdentity& device, char* buffer,
                          size_t capacity) {
  if (!device_id_is_valid(device.device_id)) return invalid_device(buffer, capacity);
  JsonWriter out(buffer, capacity);
  out.character('[');
  for (size_t i = 0; i < count; ++i) {
    if (i > 0) out.character(',');
    write_reading(out, readings[i], device);
  }
  out.character(']');
  return finish(out);
}

}  // namespace alplan::firmware
