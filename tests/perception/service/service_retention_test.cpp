// Readings older than the retention period are deleted in the background
// without stopping ingestion.
#include <catch2/catch.hpp>

#include <chrono>

#include "perception/service/home_event_store.h"
#include "perception/service/reading_ingest.h"
#include "perception/service/retention_sweeper.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;
using namespace std::chrono_literals;

namespace {

std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

ReceivedReading reading(const std::string& device, std::uint32_t seq) {
  ReceivedReading r;
  r.device = device;
  r.seq = seq;
  r.t_ms = 1700000000000ULL + seq;
  r.window_ms = 30000;
  r.beats = 2;
  r.rejected_fraction = 0.5;
  r.motion = true;
  return r;
}

}  // namespace

TEST_CASE("retention: readings older than the period are deleted in chunks while ingestion goes on") {
  test::ScratchDir dir("retention");
  const DeviceRegistry registry = test::test_registry(2);
  const std::int64_t day_ms = 86400000;
  {
    // 2000 readings that arrived ten days ago, and their event.
    ReadingStore store(dir / "r.db", Durability::Normal);
    store.begin();
    for (std::uint32_t s = 0; s < 2000; ++s) store.insert_reading(reading("wb-00", s), now_ms() - 10 * day_ms);
    store.insert_stress_event({"senior-00", "wb-00", true, 1700000000000ULL, 1.0, 6}, now_ms() - 10 * day_ms);
    store.commit();
    // A live home's events: one old, one new.
    HomeEventStore home(dir / "r.db", Durability::Normal);
    home.insert({10.0, "goal", "senior-00", "", "{}"}, now_ms() - 10 * day_ms);
    home.insert({20.0, "comforted", "senior-01", "", "{}"}, now_ms());
  }
  ReadingStore store(dir / "r.db", Durability::Normal);
  StressEventQueue events(4);
  ReadingIngest ingest(store, nullptr, events, registry, 0);
  RetentionOptions retention;
  retention.days = 7;
  retention.chunk = 100;
  retention.interval = 50ms;
  RetentionSweeper sweeper(dir / "r.db", retention, log_to_stderr);
  sweeper.start();
  // Meanwhile the other wristband's readings keep being committed.
  std::uint32_t seq = 0;
  const auto give_up = std::chrono::steady_clock::now() + 20s;
  while (sweeper.deleted() < 2000 && std::chrono::steady_clock::now() < give_up) {
    CHECK(ingest.ingest("senior-01", {reading("wb-01", seq++)}) == std::vector<bool>{true});
  }
  sweeper.stop();
  CHECK(sweeper.deleted() == 2000);
  CHECK(store.readings_of("wb-00").empty());
  CHECK(store.readings_of("wb-01").size() == seq);
  CHECK(store.stress_events().empty());
  const std::vector<HomeEventRow> home_left = HomeEventStore(dir / "r.db", Durability::Normal).rows();
  REQUIRE(home_left.size() == 1);
  CHECK(home_left.front().type == "comforted");
  // A sweep with nothing old deletes nothing.
  CHECK(sweeper.sweep(now_ms()) == 0);
  CHECK_THROWS_AS(RetentionSweeper(dir / "r.db", RetentionOptions{-1.0}, log_to_stderr), std::invalid_argument);
  CHECK_THROWS_AS(RetentionSweeper(dir / "r.db", RetentionOptions{1e300}, log_to_stderr), std::invalid_argument);
}
