// What differs between wristbands and deployments, in one place. The
// per-device secrets (Wi-Fi, token, service address) are in secrets.h, which
// is not in git: copy secrets.example.h to secrets.h and fill it in.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "secrets.h"

namespace alplan::board {

// The pulse sensor's analog output. It must be an ADC1 pin: ADC2 cannot be
// read while Wi-Fi is on. On the TTGO LoRa32 (V2.1) GPIO 36 (SENSOR_VP) is
// an input-only ADC1 pin left free by the LoRa radio and the display.
inline constexpr uint8_t kPpgPin = 36;
// The core expects systolic peaks to point up. Sensors that report light
// intensity (it falls as blood volume rises) need inverting; an amplified
// "pulse sensor" module already outputs peaks up.
inline constexpr bool kInvertPpg = false;
inline constexpr float kAdcFullScale = 4095.0f;  // 12-bit; also the clipping rails

inline constexpr uint32_t kSampleRateHz = 100;
inline constexpr uint32_t kWindowMs = 30000;
inline constexpr uint32_t kHopMs = 5000;

// Offline store: 240 readings of a 5 s hop are 20 minutes without Wi-Fi, in
// 240 * 336 bytes = 79 KB of RAM; beyond that the oldest are dropped.
inline constexpr size_t kOfflineReadings = 240;
// Readings per POST: 12 of at most 335 characters fit the 4 KB body.
inline constexpr size_t kReadingsPerPost = 12;
inline constexpr size_t kPostBodyBytes = 4096;
inline constexpr uint32_t kHttpTimeoutMs = 8000;

// Back-off: Wi-Fi from 1 s to 5 min, uploads from 2 s to 5 min.
inline constexpr uint32_t kWifiRetryInitialMs = 1000;
inline constexpr uint32_t kWifiRetryMaxMs = 300000;
inline constexpr uint32_t kUploadRetryInitialMs = 2000;
inline constexpr uint32_t kUploadRetryMaxMs = 300000;

}  // namespace alplan::board
