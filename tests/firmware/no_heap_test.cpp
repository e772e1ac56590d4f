#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include "firmware/core/reading_encoder.h"
#include "firmware/core/reading_queue.h"
#include "firmware/core/wristband_core.h"
#include "perception/stress/ppg_simulator.h"
#include "tests/firmware/allocation_counter.h"

using namespace alplan;

TEST_CASE("the allocation counter sees allocations") {
  const std::size_t before = test::allocation_count();
  auto held = std::make_unique<std::vector<int>>(100);
  CHECK(test::allocation_count() >= before + 2);
}

TEST_CASE("after start-up the core, the encoder and the queue never allocate") {
  perception::PpgSimulator simulator(5);
  perception::RecordingConditions conditions;
  conditions.duration_s = 600.0;
  conditions.motion = {2.0, 3.0, 3.0};
  const std::vector<double> ppg = simulator.simulate({}, conditions).recording.ppg;

  auto core = std::make_unique<firmware::WristbandCore>(firmware::CoreConfig{});
  auto queue = std::make_unique<firmware::ReadingQueue<32>>();
  auto body = std::make_unique<char[]>(4096);
  char json[firmware::kMaxReadingJsonLength];
  std::size_t readings = 0;
  std::size_t batches = 0;

  const std::size_t before = test::allocation_count();
  for (double sample : ppg) {
    const firmware::CoreStep step = core->push_sample(static_cast<float>(sample));
    if (!step.reading_ready) continue;
    ++readings;
    const firmware::EncodeResult encoded = firmware::encode_reading(step.reading, {"wb-01", 1}, json, sizeof json);
    if (encoded.status == firmware::EncodeStatus::Ok) queue->push(json, encoded.length);
    if (readings % 10 == 0) {
      const firmware::QueuedBatch batch = queue->write_batch(body.get(), 4096, 8);
      if (batch.count > 0) ++batches;
      queue->release_before(batch.end_id);
    }
  }
  const std::size_t allocations = test::allocation_count() - before;

  CHECK(allocations == 0);
  CHECK(readings > 100);
  CHECK(batches > 10);
}

TEST_CASE("the whole core fits in a few kilobytes of static memory") {
  // What the ESP32 reserves for it; the board keeps it in a static object.
  CHECK(sizeof(firmware::WristbandCore) < 16 * 1024);
}
