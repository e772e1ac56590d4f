// HTTPS in the service itself: a client that trusts the service's CA posts
// readings; one that trusts another CA, or speaks plain HTTP, gets nothing
// through; the simulated wristbands speak it too.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "perception/service/readings_client.h"
#include "perception/service/wristband_fleet.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;
using namespace std::chrono_literals;

namespace {

std::string reading_json(std::uint32_t seq) {
  return R"({"device":"wb-00","boot":0,"seq":)" + std::to_string(seq) +
         R"(,"t_ms":1700000000000,"window_ms":30000,"hr_bpm":null,"ibi_ms":null,"sdnn_ms":null,)"
         R"("rmssd_ms":null,"beats":2,"rejected_fraction":0.5,"motion":true})";
}

SignalServiceOptions tls_options(const test::ScratchDir& dir, const test::TestCertificate& certificate) {
  SignalServiceOptions options = test::test_options(dir / "t.db");
  options.server.tls_certificate_file = certificate.certificate.string();
  options.server.tls_key_file = certificate.key.string();
  return options;
}

}  // namespace

TEST_CASE("tls: readings over HTTPS from a client that trusts the service's certificate") {
  test::ScratchDir dir("tls");
  const test::TestCertificate certificate = test::make_test_certificate(dir, "service");
  const DeviceRegistry registry = test::test_registry(1);
  auto service = test::start_service(registry, tls_options(dir, certificate), false);
  REQUIRE(service->url() == "https://127.0.0.1:" + std::to_string(service->port()));
  ReadingsClient client(parse_http_url(service->url()), 3000ms, certificate.certificate.string());
  for (std::uint32_t seq = 0; seq < 3; ++seq) {  // one keep-alive TLS connection
    const HttpResult r = client.post("/v1/readings", reading_json(seq), registry.devices()[0].token);
    INFO(r.error);
    REQUIRE(r.status == 200);
  }
  // By name too: the certificate names localhost and 127.0.0.1.
  ReadingsClient by_name(parse_http_url("https://localhost:" + std::to_string(service->port())), 3000ms,
                         certificate.certificate.string());
  CHECK(by_name.get("/healthz").status == 200);
  CHECK(service->counters().stored == 3);
}

TEST_CASE("tls: a client trusting another CA, or speaking plain HTTP, gets nothing through") {
  test::ScratchDir dir("tls-refused");
  const test::TestCertificate certificate = test::make_test_certificate(dir, "service");
  const test::TestCertificate stranger = test::make_test_certificate(dir, "stranger");
  const DeviceRegistry registry = test::test_registry(1);
  auto service = test::start_service(registry, tls_options(dir, certificate), false);
  ReadingsClient wrong_ca(parse_http_url(service->url()), 3000ms, stranger.certificate.string());
  const HttpResult refused = wrong_ca.post("/v1/readings", reading_json(0), registry.devices()[0].token);
  CHECK(refused.status == kTransportConnectFailed);
  CHECK(refused.error.find("TLS handshake with 127.0.0.1:") == 0);
  CHECK(refused.error.find("certificate verify failed") != std::string::npos);
  ReadingsClient plain({"127.0.0.1", service->port(), "", false}, 3000ms);
  CHECK(plain.post("/v1/readings", reading_json(1), registry.devices()[0].token).status < 0);
  CHECK(service->counters().stored == 0);
  // The service is unhurt.
  ReadingsClient right(parse_http_url(service->url()), 3000ms, certificate.certificate.string());
  CHECK(right.post("/v1/readings", reading_json(2), registry.devices()[0].token).status == 200);
}

TEST_CASE("tls: a certificate that cannot be loaded stops the start, naming the file") {
  test::ScratchDir dir("tls-bad");
  const test::TestCertificate certificate = test::make_test_certificate(dir, "service");
  const test::TestCertificate other = test::make_test_certificate(dir, "other");
  const DeviceRegistry registry = test::test_registry(1);
  SignalServiceOptions options = tls_options(dir, certificate);
  options.server.tls_certificate_file = (dir / "missing.pem").string();
  CHECK_THROWS_WITH(test::start_service(registry, options, false),
                    Catch::StartsWith("cannot load the TLS certificate " + (dir / "missing.pem").string()));
  options = tls_options(dir, certificate);
  options.server.tls_key_file = other.key.string();
  CHECK_THROWS_WITH(test::start_service(registry, options, false),
                    "cannot load the TLS key " + other.key.string() + ": key values mismatch");
}

TEST_CASE("tls: simulated wristbands deliver every reading over HTTPS") {
  test::ScratchDir dir("tls-fleet");
  const test::TestCertificate certificate = test::make_test_certificate(dir, "service");
  const DeviceRegistry registry = test::test_registry(3);
  auto service = test::start_service(registry, tls_options(dir, certificate), false);
  FleetOptions fleet_options;
  fleet_options.url = service->url();
  fleet_options.ca_file = certificate.certificate.string();
  fleet_options.devices = 3;
  fleet_options.rate_hz = 0.2;
  fleet_options.duration_s = 60.0;
  fleet_options.speed = 30.0;
  fleet_options.sample_rate_hz = 25.0;
  WristbandFleet fleet(registry, fleet_options);
  const FleetSummary summary = fleet.run();
  CHECK(summary.complete());
  CHECK(summary.total.made > 0);
  CHECK(service->counters().stored == summary.total.made);
}

TEST_CASE("tls: a client that connects and never starts the handshake is let go at the request deadline") {
  test::ScratchDir dir("tls-silent");
  const test::TestCertificate certificate = test::make_test_certificate(dir, "service");
  const DeviceRegistry registry = test::test_registry(1);
  SignalServiceOptions options = tls_options(dir, certificate);
  options.server.request_timeout = 500ms;
  auto service = test::start_service(registry, options, false);
  const auto start = std::chrono::steady_clock::now();
  CHECK(test::exchange_raw(service->port(), "", 5000ms).empty());  // closed without a word
  CHECK(std::chrono::steady_clock::now() - start < 3s);
}
