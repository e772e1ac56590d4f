// A short soak (the benchmark's code, seconds instead of ten minutes): with
// commits failing at random, the service restarted every few seconds and
// clients stalling mid-request, nothing acknowledged is lost and no stress
// event is raised twice or missed.
#include <catch2/catch.hpp>

#include "perception/service/service_soak.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;

TEST_CASE("soak (short): faults lose no reading and raise no event twice") {
  test::ScratchDir dir("soak");
  SoakOptions options;
  options.devices = 40;
  options.duration_s = 45.0;
  options.speed = 3.0;
  options.rate_hz = 1.0;
  options.commit_failure_rate = 0.1;
  options.restart_every_s = 4.0;
  options.stalled_clients = 4;
  options.connections = 4;
  options.work_dir = dir.path();
  const SoakReport r = run_soak(options);
  CHECK(r.offered > 0);
  CHECK(r.acknowledged == r.offered);
  CHECK(r.stored == r.offered);
  CHECK(r.lost == 0);
  CHECK(r.duplicate_events == 0);
  CHECK(r.missed_events == 0);
  CHECK(r.events_stored == 10);  // a quarter of the seniors are stressed
  // The faults happened.
  CHECK(r.commit_failures > 0);
  CHECK(r.restarts >= 2);
  CHECK(r.stalled_connections >= 4);
  CHECK(r.retries > 0);
  CHECK(r.passed());
}
