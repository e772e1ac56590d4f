// Sends readings to the service: takes the sampler's readings from the
// FreeRTOS queue, encodes them into the bounded offline queue
// (firmware/core/reading_queue.h), and while Wi-Fi is up POSTs the oldest
// ones as a JSON array to POST /v1/readings with the device's bearer token.
// A batch is released only when the service acknowledged it (2xx); what to
// do otherwise is firmware/core/upload_policy.h's decision, and the pace of
// retries firmware/core/retry_backoff.h's.
#pragma once

#include <freertos/FreeRTOS.h>
#include <freertos/queue.h>
#include <stdint.h>

#include "board_config.h"
#include "reading_encoder.h"
#include "reading_queue.h"
#include "retry_backoff.h"

namespace alplan::board {

class ReadingUploader {
 public:
  ReadingUploader();

  // Where the readings come from, and who sends them.
  void begin(QueueHandle_t readings, const firmware::DeviceIdentity& device);

  // Call every loop: drains the sampler's queue, and POSTs a batch when
  // online and not backing off. A POST blocks for up to kHttpTimeoutMs.
  void poll(uint32_t now_ms, bool online);

  size_t pending() const { return queue_.size(); }
  uint64_t dropped() const { return queue_.dropped(); }      // queue full: oldest dropped
  uint64_t discarded() const { return discarded_; }          // refused by the service (4xx)

 private:
  void drain_sampler();
  void send_batch(uint32_t now_ms);
  int post(char* body, size_t length);

  QueueHandle_t readings_ = nullptr;
  firmware::DeviceIdentity device_{};
  firmware::ReadingQueue<kOfflineReadings> queue_;
  firmware::RetryBackoff backoff_;
  uint32_t next_attempt_ms_ = 0;
  uint64_t discarded_ = 0;
  char body_[kPostBodyBytes];
};

}  // namespace alplan::board
