// Stress detection inside the ingest: events for the senior whose readings
// flip the decision, stored with the readings and published to the queue;
// late readings not voted on; the detector primed from the database after a
// restart.
#include <catch2/catch.hpp>

#include "perception/service/reading_ingest.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;

namespace {

// Typical windows from a fixed time in 2023.
ReceivedReading window(const std::string& device, std::uint32_t seq, bool stressed) {
  return test::typical_window(device, seq, stressed, 1700000000000ULL);
}

std::unique_ptr<perception::ClassifierStressDetector> detector() { return test::test_stress_detector(); }

}  // namespace

TEST_CASE("the trained classifier tells the typical calm window from the stressed one") {
  CHECK(test::test_classifier().predict(window_features_of(window("wb-00", 0, false))) == 0);
  CHECK(test::test_classifier().predict(window_features_of(window("wb-00", 0, true))) == 1);
}

TEST_CASE("ingest: a senior's stress and calm become stored and published events, late readings do not vote") {
  test::ScratchDir dir("stress-ingest");
  ReadingStore store(dir / "s.db", Durability::Normal);
  StressEventQueue events(16);
  const DeviceRegistry registry = test::test_registry(2);
  auto stress = detector();
  ReadingIngest ingest(store, stress.get(), events, registry, 24);
  std::uint32_t seq = 0;
  for (int i = 0; i < 6; ++i) ingest.ingest("senior-00", {window("wb-00", seq++, false)});
  CHECK_FALSE(events.try_pop());
  for (int i = 0; i < 6; ++i) ingest.ingest("senior-00", {window("wb-00", seq++, true)});
  const auto became_stressed = events.try_pop();
  REQUIRE(became_stressed);
  CHECK(became_stressed->stressed);
  CHECK(became_stressed->senior == "senior-00");
  CHECK(became_stressed->device == "wb-00");
  CHECK(became_stressed->stressed_fraction >= 0.6);
  CHECK_FALSE(events.try_pop());
  // The other senior, calm all along, is untouched.
  for (std::uint32_t s = 0; s < 8; ++s) ingest.ingest("senior-01", {window("wb-01", s, false)});
  CHECK_FALSE(events.try_pop());
  // Stressed windows arriving late (older than what was voted on) change nothing.
  for (std::uint32_t s = 100; s < 110; ++s) {
    ReceivedReading late = window("wb-01", s, true);
    late.t_ms = 1600000000000ULL + s;
    ingest.ingest("senior-01", {late});
  }
  CHECK_FALSE(events.try_pop());
  CHECK(ingest.counters().late == 10);
  for (int i = 0; i < 6; ++i) ingest.ingest("senior-00", {window("wb-00", seq++, false)});
  const auto calm = events.try_pop();
  REQUIRE(calm);
  CHECK_FALSE(calm->stressed);
  const auto stored = store.stress_events();
  REQUIRE(stored.size() == 2);
  CHECK(stored[0].stressed);
  CHECK(stored[0].t_ms == became_stressed->t_ms);
  CHECK_FALSE(stored[1].stressed);
  CHECK(ingest.counters().became_stressed == 1);
  CHECK(ingest.counters().became_calm == 1);
}

TEST_CASE("ingest: after a restart the detector remembers a stressed senior, so no second 'stressed' event") {
  test::ScratchDir dir("stress-restart");
  const DeviceRegistry registry = test::test_registry(1);
  std::uint32_t seq = 0;
  {
    ReadingStore store(dir / "s.db", Durability::Normal);
    StressEventQueue events(16);
    auto stress = detector();
    ReadingIngest ingest(store, stress.get(), events, registry, 24);
    for (int i = 0; i < 8; ++i) ingest.ingest("senior-00", {window("wb-00", seq++, true)});
    CHECK(events.size() == 1);
  }
  ReadingStore store(dir / "s.db", Durability::Normal);
  StressEventQueue events(16);
  auto stress = detector();
  ReadingIngest ingest(store, stress.get(), events, registry, 24);
  CHECK(stress->state("senior-00")->stressed);
  for (int i = 0; i < 4; ++i) ingest.ingest("senior-00", {window("wb-00", seq++, true)});
  CHECK(events.size() == 0);
  CHECK(store.stress_events().size() == 1);
  // The readings the restart replayed are not voted on again when re-sent.
  CHECK(ingest.ingest("senior-00", {window("wb-00", 3, true)}) == std::vector<bool>{false});
}
