#include "wifi_link.h"

#include <Arduino.h>
#include <WiFi.h>
#include <esp_random.h>
#include <sys/time.h>
#include <time.h>

#include "board_config.h"

namespace alplan::board {

namespace {
// An attempt that has not connected by then is abandoned and backed off.
constexpr uint32_t kAttemptTimeoutMs = 20000;
// Any time after 2020 means NTP has answered (the RTC starts at 1970).
constexpr time_t kClockSetAfter = 1577836800;
}  // namespace

WifiLink::WifiLink() : backoff_(kWifiRetryInitialMs, kWifiRetryMaxMs) {}

bool WifiLink::connected() const { return WiFi.status() == WL_CONNECTED; }

bool WifiLink::clock_set() const { return time(nullptr) > kClockSetAfter; }

uint64_t WifiLink::unix_time_ms() {
  timeval now{};
  gettimeofday(&now, nullptr);
  return static_cast<uint64_t>(now.tv_sec) * 1000u + static_cast<uint64_t>(now.tv_usec) / 1000u;
}

void WifiLink::start_attempt(uint32_t now_ms) {
  WiFi.disconnect(true);
  WiFi.mode(WIFI_STA);
  // Reconnection is ours (with back-off), not the driver's.
  WiFi.setAutoReconnect(false);
  WiFi.begin(ALPLAN_WIFI_SSID, ALPLAN_WIFI_PASSWORD);
  attempting_ = true;
  attempt_started_ms_ = now_ms;
}

void WifiLink::poll(uint32_t now_ms) {
  if (connected()) {
    if (!was_connected_) {
      was_connected_ = true;
      attempting_ = false;
      backoff_.reset();
      if (!ntp_started_) {
        configTime(0, 0, "pool.ntp.org", "time.google.com");
        ntp_started_ = true;
      }
    }
    return;
  }
  if (was_connected_) {
    // Just lost: try again at once; back-off applies from the next failure.
    was_connected_ = false;
    attempting_ = false;
    next_attempt_ms_ = now_ms;
  }
  if (attempting_) {
    if (static_cast<uint32_t>(now_ms - attempt_started_ms_) < kAttemptTimeoutMs) return;
    attempting_ = false;
    next_attempt_ms_ = now_ms + backoff_.next_delay_ms(esp_random());
    return;
  }
  if (static_cast<int32_t>(now_ms - next_attempt_ms_) >= 0) start_attempt(now_ms);
}

}  // namespace alplan::board
