#include <catch2/catch.hpp>

#include <thread>

#include "perception/service/reading_ingest.h"
#include "perception/service/reading_store.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;

namespace {

ReceivedReading reading(const std::string& device, std::uint32_t boot, std::uint32_t seq, double hr = 70.0) {
  ReceivedReading r;
  r.device = device;
  r.boot = boot;
  r.seq = seq;
  r.t_ms = 1700000000000ULL + 5000ULL * seq + 1000000ULL * boot;
  r.window_ms = 30000;
  r.hr_bpm = hr;
  r.ibi_ms = 60000.0 / hr;
  r.sdnn_ms = 40.0;
  r.rmssd_ms = std::nullopt;
  r.beats = 35;
  r.rejected_fraction = 0.0;
  return r;
}

}  // namespace

TEST_CASE("the store keeps a reading once per (device, boot, seq), with every field, across reopening") {
  test::ScratchDir dir("store");
  {
    ReadingStore store(dir / "r.db");
    store.begin();
    CHECK(store.insert_reading(reading("wb-00", 1, 5), 1));
    CHECK_FALSE(store.insert_reading(reading("wb-00", 1, 5, 99.0), 2));  // a duplicate keeps the first
    CHECK(store.insert_reading(reading("wb-00", 2, 5), 3));              // another boot
    CHECK(store.insert_reading(reading("wb-01", 1, 5), 4));              // another device
    store.insert_stress_event({"senior-00", "wb-00", true, 1700000025000ULL, 0.75, 4}, 5);
    store.commit();
    store.begin();
    CHECK(store.insert_reading(reading("wb-00", 1, 6), 6));
    store.rollback();  // not committed: gone
  }
  ReadingStore again(dir / "r.db", Durability::Full);
  CHECK(again.count_readings() == 3);
  const auto stored = again.readings_of("wb-00");
  REQUIRE(stored.size() == 2);
  CHECK(stored[0].boot == 1);
  CHECK(*stored[0].hr_bpm == 70.0);
  CHECK_FALSE(stored[0].rmssd_ms.has_value());
  CHECK(stored[0].t_ms == reading("wb-00", 1, 5).t_ms);
  const auto events = again.stress_events();
  REQUIRE(events.size() == 1);
  CHECK(events[0].senior == "senior-00");
  CHECK(events[0].stressed);
  CHECK(events[0].stressed_fraction == 0.75);
  ReadingStore reader(dir / "r.db", Durability::Normal, StoreAccess::ReadOnly);
  CHECK(reader.count_readings() == 3);
}

TEST_CASE("the store refuses a database of another schema version, naming the file") {
  test::ScratchDir dir("store-version");
  {
    SqliteDatabase db(dir / "other.db");
    db.execute("PRAGMA user_version = 7");
  }
  CHECK_THROWS_WITH(ReadingStore(dir / "other.db"), Catch::Contains("other.db has schema version 7"));
  CHECK_THROWS_WITH(ReadingStore(dir / "missing-dir" / "x.db"), Catch::Contains("cannot open"));
}

TEST_CASE("ingest: duplicates, out-of-order arrival and gaps per device") {
  test::ScratchDir dir("ingest");
  ReadingStore store(dir / "i.db", Durability::Normal);
  StressEventQueue events(16);
  const DeviceRegistry registry = test::test_registry(2);
  ReadingIngest ingest(store, nullptr, events, registry, 0);
  CHECK(ingest.ingest("senior-00", {reading("wb-00", 0, 0), reading("wb-00", 0, 1)}) == std::vector<bool>{true, true});
  // Re-sent, with a new one behind it; then one arriving late; then a jump.
  CHECK(ingest.ingest("senior-00", {reading("wb-00", 0, 1), reading("wb-00", 0, 2)}) == std::vector<bool>{false, true});
  CHECK(ingest.ingest("senior-00", {reading("wb-00", 0, 6)}) == std::vector<bool>{true});
  CHECK(ingest.missing_by_device().at("wb-00") == 3);  // 3, 4, 5
  CHECK(ingest.ingest("senior-00", {reading("wb-00", 0, 4), reading("wb-00", 0, 4)}) == std::vector<bool>{true, false});
  CHECK(ingest.missing_by_device().at("wb-00") == 2);
  CHECK(ingest.ingest("senior-00", {reading("wb-00", 1, 0)}) == std::vector<bool>{true});  // a reboot: no gap
  CHECK(ingest.missing_by_device().at("wb-00") == 2);
  const IngestCounters c = ingest.counters();
  CHECK(c.stored == 6);
  CHECK(c.duplicates == 2);
  CHECK(store.count_readings() == 6);

  // A new ingest on the same database knows the gaps.
  ReadingIngest reopened(store, nullptr, events, registry, 0);
  CHECK(reopened.missing_by_device().at("wb-00") == 2);
}

TEST_CASE("ingest: concurrent batches are committed in groups, every reading exactly once") {
  test::ScratchDir dir("group-commit");
  ReadingStore store(dir / "g.db", Durability::Full);
  StressEventQueue events(16);
  const DeviceRegistry registry = test::test_registry(8);
  ReadingIngest ingest(store, nullptr, events, registry, 0);
  std::vector<std::thread> threads;
  std::atomic<std::uint64_t> acknowledged{0};
  for (int d = 0; d < 8; ++d) {
    threads.emplace_back([&, d] {
      const std::string device = registry.devices()[static_cast<std::size_t>(d)].id;
      for (std::uint32_t seq = 0; seq < 60; seq += 3) {
        // Each batch overlaps the previous one by one reading: a re-send.
        std::vector<ReceivedReading> batch;
        for (std::uint32_t k = (seq == 0 ? 0 : seq - 1); k < seq + 3; ++k) batch.push_back(reading(device, 0, k));
        const auto stored = ingest.ingest("senior", batch);
        for (bool s : stored) acknowledged += s ? 1 : 0;
      }
    });
  }
  for (std::thread& t : threads) t.join();
  CHECK(acknowledged == 8 * 60);
  CHECK(store.count_readings() == 8 * 60);
  const IngestCounters c = ingest.counters();
  CHECK(c.stored == 8 * 60);
  CHECK(c.duplicates == 8 * 19);
  CHECK(c.batches == 8 * 20);
  CHECK(c.commits <= c.batches);
  for (const auto& [device, missing] : ingest.missing_by_device()) CHECK(missing == 0);
}
