#include "wristband_app.h"

#include <Arduino.h>
#include <Preferences.h>

#include "board_config.h"
#include "wristband_core.h"

namespace alplan::board {

namespace {

// Counts power-ups in flash, so that (device, boot, seq) identifies a
// reading across restarts; one flash write per boot.
uint32_t next_boot_number() {
  Preferences preferences;
  preferences.begin("alplan", false);
  const uint32_t boot = preferences.getUInt("boot", 0) + 1;
  preferences.putUInt("boot", boot);
  preferences.end();
  return boot;
}

// The sampler's queue only bridges two tasks; the uploader drains it every
// loop (20 ms) and readings come every few seconds.
constexpr UBaseType_t kSamplerQueueLength = 8;

}  // namespace

void WristbandApp::setup() {
  Serial.begin(115200);
  readings_ = xQueueCreate(kSamplerQueueLength, sizeof(firmware::Reading));
  uploader_.begin(readings_, firmware::DeviceIdentity{ALPLAN_DEVICE_ID, next_boot_number()});
}

void WristbandApp::loop() {
  const uint32_t now = millis();
  wifi_.poll(now);
  // Readings carry Unix time, so sampling starts once the clock is set (the
  // first time Wi-Fi is up after power-on); the RTC keeps it from then on.
  if (!sampling_started_ && wifi_.clock_set()) start_sampling();
  uploader_.poll(now, wifi_.connected());
  delay(20);
}

void WristbandApp::start_sampling() {
  sampling_started_ = true;
  firmware::CoreConfig config;
  config.sample_rate_hz = static_cast<float>(kSampleRateHz);
  config.window_ms = kWindowMs;
  config.hop_ms = kHopMs;
  config.start_time_ms = WifiLink::unix_time_ms();
  config.signal_quality.clip_low = 0.0f;
  config.signal_quality.clip_high = kAdcFullScale;
  if (!sampler_.begin(config, readings_)) {
    log_e("sampling did not start (configuration: %s)",
          firmware::config_error_name(firmware::check_config(config)));
  }
}

}  // namespace alplan::board
