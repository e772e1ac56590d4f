// Samples the PPG sensor at a fixed rate and runs the portable core on it.
// A hardware timer's interrupt only notifies a task (the ADC driver must not
// be used from an interrupt); the task reads the ADC once per notification,
// so late samples are late, never lost, and feeds WristbandCore. Each
// reading the core makes goes into a FreeRTOS queue for the uploader, the
// only thing this task shares.
#pragma once

#include <Arduino.h>
#include <atomic>
#include <freertos/FreeRTOS.h>
#include <freertos/queue.h>
#include <freertos/task.h>

#include "wristband_core.h"

namespace alplan::board {

class PpgSampler {
 public:
  // Starts sampling with `config` (sample 0 is now); readings go to
  // `readings`, a queue of firmware::Reading. False when the configuration
  // is invalid or the timer or the task cannot be had.
  bool begin(const firmware::CoreConfig& config, QueueHandle_t readings);

  // Readings the uploader's queue had no room for (it drains every loop).
  uint32_t readings_lost() const { return readings_lost_.load(); }

 private:
  static void IRAM_ATTR on_timer(void* self);
  static void run_task(void* self);
  void run();

  firmware::CoreConfig config_{};
  alignas(firmware::WristbandCore) unsigned char core_storage_[sizeof(firmware::WristbandCore)];
  firmware::WristbandCore* core_ = nullptr;
  QueueHandle_t readings_ = nullptr;
  TaskHandle_t task_ = nullptr;
  hw_timer_t* timer_ = nullptr;
  std::atomic<uint32_t> readings_lost_{0};
};

}  // namespace alplan::board
