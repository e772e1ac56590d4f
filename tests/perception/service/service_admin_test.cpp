// /healthz and /metrics: on the admin listener (loopback by default), not on
// the wristbands' port once that faces the network, and nothing per device
// or senior in them unless asked.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "perception/service/readings_client.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;
using namespace std::chrono_literals;
using nlohmann::json;

namespace {

std::string reading_json(std::uint32_t seq) {
  return R"({"device":"wb-00","boot":0,"seq":)" + std::to_string(seq) +
         R"(,"t_ms":1700000000000,"window_ms":30000,"hr_bpm":null,"ibi_ms":null,"sdnn_ms":null,)"
         R"("rmssd_ms":null,"beats":2,"rejected_fraction":0.5,"motion":true})";
}

}  // namespace

TEST_CASE("admin: on a network-facing service /metrics and /healthz are on the loopback admin listener only") {
  test::ScratchDir dir("admin");
  const DeviceRegistry registry = test::test_registry(1);
  SignalServiceOptions options = test::test_options(dir / "a.db");
  options.server.bind_address = "0.0.0.0";
  auto service = test::start_service(registry, options, false);
  REQUIRE(service->admin_port() != 0);
  REQUIRE(service->admin_port() != service->port());
  CHECK(service->admin_url() == "http://127.0.0.1:" + std::to_string(service->admin_port()));
  ReadingsClient wristband({"127.0.0.1", service->port(), ""}, 2000ms);
  ReadingsClient admin({"127.0.0.1", service->admin_port(), ""}, 2000ms);
  CHECK(wristband.post("/v1/readings", reading_json(0), registry.devices()[0].token).status == 200);
  const HttpResult metrics_on_public = wristband.get("/metrics");
  CHECK(metrics_on_public.status == 404);
  CHECK(json::parse(metrics_on_public.body)["error"] == "no such path; this listener serves POST /v1/readings only");
  CHECK(wristband.get("/healthz").status == 404);
  CHECK(admin.get("/healthz").status == 200);
  const HttpResult metrics = admin.get("/metrics");
  REQUIRE(metrics.status == 200);
  CHECK(metrics.body.find("alplan_readings_stored_total 1\n") != std::string::npos);
  // Readings are not taken on the admin port.
  CHECK(admin.post("/v1/readings", reading_json(1), registry.devices()[0].token).status == 404);
}

TEST_CASE("admin: a loopback service serves both on its port too, as before") {
  test::ScratchDir dir("admin-loopback");
  const DeviceRegistry registry = test::test_registry(1);
  auto service = test::start_service(registry, test::test_options(dir / "a.db"), false);
  ReadingsClient client({"127.0.0.1", service->port(), ""}, 2000ms);
  CHECK(client.get("/healthz").status == 200);
  CHECK(client.get("/metrics").status == 200);
}

TEST_CASE("admin: by default no device id or stress transition in /metrics, none in /healthz - detailed on request") {
  test::ScratchDir dir("admin-detail");
  const DeviceRegistry registry = test::test_registry(1);
  SignalServiceOptions options = test::test_options(dir / "a.db");
  auto service = test::start_service(registry, options, false);
  ReadingsClient client({"127.0.0.1", service->admin_port(), ""}, 2000ms);
  ReadingsClient wristband({"127.0.0.1", service->port(), ""}, 2000ms);
  CHECK(wristband.post("/v1/readings", reading_json(3), registry.devices()[0].token).status == 200);
  std::string metrics = client.get("/metrics").body;
  CHECK(metrics.find("wb-00") == std::string::npos);
  CHECK(metrics.find("alplan_stress_events_total") == std::string::npos);
  CHECK(metrics.find("alplan_readings_missing 3\n") != std::string::npos);
  CHECK_FALSE(json::parse(client.get("/healthz").body).contains("stress_events"));
  service->stop();

  options.limits.detailed_metrics = true;
  auto detailed = test::start_service(registry, options, false);
  ReadingsClient admin({"127.0.0.1", detailed->admin_port(), ""}, 2000ms);
  metrics = admin.get("/metrics").body;
  CHECK(metrics.find("alplan_readings_missing{device=\"wb-00\"} 3\n") != std::string::npos);
  CHECK(metrics.find("alplan_stress_events_total{state=\"stressed\"} 0\n") != std::string::npos);
  CHECK(json::parse(admin.get("/healthz").body).contains("stress_events"));
}
