// The wristband application: Wi-Fi, the sampler and the uploader, wired
// together and driven from Arduino's setup() and loop().
#pragma once

#include <freertos/FreeRTOS.h>
#include <freertos/queue.h>

#include "ppg_sampler.h"
#include "reading_uploader.h"
#include "wifi_link.h"

namespace alplan::board {

class WristbandApp {
 public:
  void setup();
  void loop();

 private:
  void start_sampling();

  WifiLink wifi_;
  PpgSampler sampler_;
  ReadingUploader uploader_;
  QueueHandle_t readings_ = nullptr;
  bool sampling_started_ = false;
};

}  // namespace alplan::board
