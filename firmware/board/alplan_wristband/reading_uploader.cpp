#include "reading_uploader.h"

#include <Arduino.h>
#include <HTTPClient.h>
#include <WiFiClientSecure.h>
#include <esp_random.h>

#include "upload_policy.h"

namespace alplan::board {

ReadingUploader::ReadingUploader() : backoff_(kUploadRetryInitialMs, kUploadRetryMaxMs) {}

void ReadingUploader::begin(QueueHandle_t readings, const firmware::DeviceIdentity& device) {
  readings_ = readings;
  device_ = device;
}

void ReadingUploader::drain_sampler() {
  firmware::Reading reading;
  char json[firmware::kMaxReadingJsonLength];
  while (xQueueReceive(readings_, &reading, 0) == pdTRUE) {
    const firmware::EncodeResult encoded = firmware::encode_reading(reading, device_, json, sizeof json);
    if (encoded.status == firmware::EncodeStatus::Ok) {
      queue_.push(json, encoded.length);
    } else {
      log_e("reading %u not encoded (device id invalid?)", static_cast<unsigned>(reading.sequence));
    }
  }
}

int ReadingUploader::post(char* body, size_t length) {
  // With a CA set the handshake requires a certificate chaining to it and
  // naming the URL's host (firmware/README.md); never setInsecure().
  WiFiClientSecure tls;
  tls.setCACert(ALPLAN_SERVICE_CA_PEM);
  HTTPClient http;
  http.setTimeout(kHttpTimeoutMs);
  if (!http.begin(tls, ALPLAN_READINGS_URL)) return HTTPC_ERROR_CONNECTION_REFUSED;
  http.addHeader("Content-Type", "application/json");
  http.addHeader("Authorization", "Bearer " ALPLAN_DEVICE_TOKEN);
  const int status = http.POST(reinterpret_cast<uint8_t*>(body), length);
  http.end();
  return status;
}

void ReadingUploader::send_batch(uint32_t now_ms) {
  const firmware::QueuedBatch batch = queue_.write_batch(body_, sizeof body_, kReadingsPerPost);
  if (batch.count == 0) return;
  const int status = post(body_, batch.length);
  switch (firmware::classify_upload_status(status)) {
    case firmware::UploadVerdict::Delivered:
      queue_.release_before(batch.end_id);
      backoff_.reset();
      return;
    case firmware::UploadVerdict::Discard:
      log_e("service refused %u readings with HTTP %d; dropping them", static_cast<unsigned>(batch.count), status);
      queue_.release_before(batch.end_id);
      discarded_ += batch.count;
      return;
    case firmware::UploadVerdict::RetryLater:
      next_attempt_ms_ = now_ms + backoff_.next_delay_ms(esp_random());
      log_w("upload failed (HTTP %d); retrying in %u ms", status, static_cast<unsigned>(next_attempt_ms_ - now_ms));
      return;
  }
}

void ReadingUploader::poll(uint32_t now_ms, bool online) {
  if (readings_ == nullptr) return;
  drain_sampler();
  if (!online || queue_.empty()) return;
  if (static_cast<int32_t>(now_ms - next_attempt_ms_) < 0) return;
  send_batch(now_ms);
}

}  // namespace alplan::board
