#include "ppg_sampler.h"

#include <new>

#include "board_config.h"

namespace alplan::board {

namespace {
constexpr uint32_t kTimerTickHz = 1000000;  // 1 us ticks
constexpr uint32_t kTaskStackBytes = 4096;
// Core 1, above the Arduino loop task (priority 1) that shares it, so a slow
// POST never delays a sample; the Wi-Fi stack runs on core 0.
constexpr UBaseType_t kTaskPriority = 10;
constexpr BaseType_t kSamplingCore = 1;
}  // namespace

bool PpgSampler::begin(const firmware::CoreConfig& config, QueueHandle_t readings) {
  if (firmware::check_config(config) != firmware::ConfigError::None) return false;
  config_ = config;
  readings_ = readings;
  // Placement new into storage inside this object: the core (about 12 KB)
  // must not live on a task's stack, and the firmware uses no heap for it.
  core_ = new (core_storage_) firmware::WristbandCore(config_);

  analogReadResolution(12);
  analogSetPinAttenuation(kPpgPin, ADC_11db);
  if (xTaskCreatePinnedToCore(&PpgSampler::run_task, "ppg", kTaskStackBytes, this, kTaskPriority, &task_,
                              kSamplingCore) != pdPASS) {
    return false;
  }
  timer_ = timerBegin(kTimerTickHz);
  if (timer_ == nullptr) return false;
  timerAttachInterruptArg(timer_, &PpgSampler::on_timer, this);
  timerAlarm(timer_, kTimerTickHz / static_cast<uint32_t>(config_.sample_rate_hz), true, 0);
  return true;
}

void IRAM_ATTR PpgSampler::on_timer(void* self) {
  BaseType_t woken = pdFALSE;
  vTaskNotifyGiveFromISR(static_cast<PpgSampler*>(self)->task_, &woken);
  if (woken == pdTRUE) portYIELD_FROM_ISR();
}

void PpgSampler::run_task(void* self) { static_cast<PpgSampler*>(self)->run(); }

void PpgSampler::run() {
  for (;;) {
    // pdFALSE: take one notification at a time, so a backlog of ticks
    // becomes that many samples.
    ulTaskNotifyTake(pdFALSE, portMAX_DELAY);
    const float raw = static_cast<float>(analogRead(kPpgPin));
    const float sample = kInvertPpg ? kAdcFullScale - raw : raw;
    const firmware::CoreStep step = core_->push_sample(sample);
    if (step.reading_ready && xQueueSend(readings_, &step.reading, 0) != pdTRUE) {
      readings_lost_.fetch_add(1);
    }
  }
}

}  // namespace alplan::board
