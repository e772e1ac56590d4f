// One reading: the features of one window, numbered and stamped so that the
// service can tell lost readings (gaps in `sequence` within a boot) from
// duplicates (a (device, boot, sequence) seen before, e.g. a batch re-sent
// after a lost HTTP response).
#pragma once

#include <stdint.h>

#include "window_features.h"

namespace alplan::firmware {

struct Reading {
  uint32_t sequence = 0;      // 0, 1, 2, ... since the core started
  uint64_t timestamp_ms = 0;  // the end of the window, on the clock given to the core
  uint32_t window_ms = 0;     // the window covers (timestamp_ms - window_ms, timestamp_ms]
  WindowFeatures features{};
};

// Who sent a reading. `device_id` is 1-32 characters of [A-Za-z0-9._-] (it
// goes into JSON and the service's keys unescaped); `boot` counts the
// device's power-ups, so (device_id, boot, sequence) is unique.
struct DeviceIdentity {
  const char* device_id = "";
  uint32_t boot = 0;
};

}  // namespace alplan::firmware
