// The wristband: PPG sampled at a fixed rate and turned into readings by the
// portable core (firmware/core), readings sent to the service over Wi-Fi and
// kept in RAM while offline. Board: TTGO LoRa32 (ESP32), Arduino core for
// ESP32 3.x. Build: see firmware/README.md.
//
// The application is one object at file scope: Arduino's setup() and loop()
// take no arguments, so this is where its state has to live (about 100 KB,
// too much for any task's stack). Everything with logic is in the core and
// tested on the host.
#include "wristband_app.h"

alplan::board::WristbandApp wristband;

void setup() { wristband.setup(); }

void loop() { wristband.loop(); }
