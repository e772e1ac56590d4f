// Stopping the service while a batch is being committed: the client whose
// batch was committed hears so before the connections close.
#include <catch2/catch.hpp>

#include <future>
#include <thread>

#include <nlohmann/json.hpp>

#include "perception/service/readings_client.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;
using namespace std::chrono_literals;

TEST_CASE("shutdown: a batch committing while the service stops is answered 200 and stored - later ones get 503") {
  test::ScratchDir dir("shutdown");
  const DeviceRegistry registry = test::test_registry(1);
  SignalServiceOptions options = test::test_options(dir / "s.db");
  // A slow disk: every commit takes 400 ms.
  options.commit_veto = [] {
    std::this_thread::sleep_for(400ms);
    return false;
  };
  auto service = test::start_service(registry, options, false);
  const std::string body =
      R"({"device":"wb-00","boot":0,"seq":0,"t_ms":1700000000000,"window_ms":30000,"hr_bpm":null,"ibi_ms":null,)"
      R"("sdnn_ms":null,"rmssd_ms":null,"beats":2,"rejected_fraction":0.5,"motion":true})";
  // A second client with a keep-alive connection open before the stop.
  ReadingsClient second({"127.0.0.1", service->port(), ""}, 5000ms);
  REQUIRE(second.get("/healthz").status == 200);
  auto answer = std::async(std::launch::async, [&] {
    ReadingsClient client({"127.0.0.1", service->port(), ""}, 5000ms);
    return client.post("/v1/readings", body, registry.devices()[0].token);
  });
  // The request is in the handler, its commit under way, when stop() comes.
  for (int i = 0; i < 200 && service->metrics().open_connections() < 2; ++i) std::this_thread::sleep_for(5ms);
  std::this_thread::sleep_for(150ms);
  auto stopped = std::async(std::launch::async, [&] { service->stop(); });
  std::this_thread::sleep_for(50ms);  // stop() is waiting for the commit
  const HttpResult refused = second.get("/healthz");
  CHECK(refused.status == 503);
  CHECK(refused.body == R"({"error":"the service is stopping; retry later","reason":"shutting_down"})");
  stopped.get();
  const HttpResult r = answer.get();
  CHECK(r.status == 200);
  CHECK(r.error.empty());
  CHECK(service->counters().stored == 1);
  // Stopped: nothing listens any more.
  ReadingsClient late({"127.0.0.1", service->port(), ""}, 1000ms);
  CHECK(late.get("/healthz").status < 0);
}
