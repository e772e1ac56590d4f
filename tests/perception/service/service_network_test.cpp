// The service over real loopback connections: what only the network side
// can get wrong (parse errors, limits, timeouts, slow and many clients), and
// two services in one process.
#include <catch2/catch.hpp>

#include <thread>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <nlohmann/json.hpp>

#include "perception/service/readings_client.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;
using namespace std::chrono_literals;
namespace net = boost::asio;
using nlohmann::json;

namespace {

std::string reading_json(const std::string& device, std::uint32_t seq) {
  return R"([{"device":")" + device + R"(","boot":0,"seq":)" + std::to_string(seq) +
         R"(,"t_ms":1700000000000,"window_ms":30000,"hr_bpm":null,"ibi_ms":null,"sdnn_ms":null,)"
         R"("rmssd_ms":null,"beats":2,"rejected_fraction":0.5,"motion":true}])";
}

std::string post_text(const std::string& token, const std::string& body, const std::string& extra_headers = "") {
  return "POST /v1/readings HTTP/1.1\r\nHost: x\r\nConnection: close\r\nContent-Type: application/json\r\n"
         "Authorization: Bearer " + token + "\r\n" + extra_headers + "Content-Length: " + std::to_string(body.size()) +
         "\r\n\r\n" + body;
}

std::string error_reason(const std::string& raw) { return json::parse(test::body_of(raw))["reason"]; }

HttpResult healthz(std::uint16_t port) {
  ReadingsClient client({"127.0.0.1", port, ""}, 2000ms);
  return client.get("/healthz");
}

}  // namespace

TEST_CASE("network: readings over a keep-alive connection, then the bad requests only a parser sees") {
  test::ScratchDir dir("network");
  const DeviceRegistry registry = test::test_registry(2);
  auto service = test::start_service(registry, test::test_options(dir / "n.db"), false);
  const std::uint16_t port = service->port();
  ReadingsClient client({"127.0.0.1", port, ""}, 2000ms);
  for (std::uint32_t seq = 0; seq < 5; ++seq) {
    const HttpResult r = client.post("/v1/readings", reading_json("wb-00", seq).substr(1, reading_json("wb-00", seq).size() - 2),
                                     registry.devices()[0].token);
    REQUIRE(r.status == 200);
    CHECK(json::parse(r.body)["stored"] == 1);
  }
  std::string raw = test::exchange_raw(port, "GARBAGE\r\n\r\n");
  CHECK(test::status_of(raw) == 400);
  CHECK(error_reason(raw) == "malformed_http");
  raw = test::exchange_raw(port, "GET /healthz HTTP/1.1\r\nHost: x\r\n" + std::string(9000, 'a') + ": b\r\n\r\n");
  CHECK(test::status_of(raw) == 431);
  CHECK(error_reason(raw) == "header_too_large");
  // A body announced too large is refused before it is sent.
  raw = test::exchange_raw(port, "POST /v1/readings HTTP/1.1\r\nHost: x\r\nContent-Length: 100000000\r\n\r\n{");
  CHECK(test::status_of(raw) == 413);
  CHECK(error_reason(raw) == "body_too_large");
  // Chunked, growing past the limit.
  std::string chunked = "POST /v1/readings HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n";
  for (int i = 0; i < 80; ++i) chunked += "400\r\n" + std::string(1024, ' ') + "\r\n";
  raw = test::exchange_raw(port, chunked + "0\r\n\r\n");
  CHECK(test::status_of(raw) == 413);
  raw = test::exchange_raw(port, post_text(registry.devices()[1].token, "[1,2"));
  CHECK(test::status_of(raw) == 400);
  CHECK(error_reason(raw) == "malformed_json");
  raw = test::exchange_raw(port, "DELETE /v1/readings HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
  CHECK(test::status_of(raw) == 405);
  // curl's way with large bodies: Expect: 100-continue.
  raw = test::exchange_raw(port, post_text(registry.devices()[1].token, reading_json("wb-01", 0), "Expect: 100-continue\r\n"));
  CHECK(raw.rfind("HTTP/1.1 100 Continue\r\n\r\nHTTP/1.1 200 OK", 0) == 0);
  CHECK(healthz(port).status == 200);
}

TEST_CASE("network: a slowloris gets 408 at the deadline and starves nobody, idle connections are closed") {
  test::ScratchDir dir("slowloris");
  const DeviceRegistry registry = test::test_registry(1);
  SignalServiceOptions options = test::test_options(dir / "s.db");
  options.server.request_timeout = 1000ms;
  options.server.io_threads = 1;  // one I/O thread: a blocking slow client would stall everything
  auto service = test::start_service(registry, options, false);
  const std::uint16_t port = service->port();

  std::string slow_answer;
  std::thread slowloris([&] {
    net::io_context io;
    net::ip::tcp::socket socket(io);
    socket.connect({net::ip::make_address("127.0.0.1"), port});
    const std::string request = post_text(registry.devices()[0].token, reading_json("wb-00", 0));
    boost::system::error_code error;
    for (std::size_t i = 0; i < request.size() && !error; ++i) {  // a byte every 50 ms: would take 20 s
      net::write(socket, net::buffer(&request[i], 1), error);
      std::this_thread::sleep_for(50ms);
      if (socket.available(error) > 0) break;
    }
    char chunk[2048];
    while (!error) slow_answer.append(chunk, socket.read_some(net::buffer(chunk), error));
  });
  const auto start = std::chrono::steady_clock::now();
  int served = 0;
  while (std::chrono::steady_clock::now() - start < 900ms) {
    const HttpResult r = healthz(port);
    CHECK(r.status == 200);
    CHECK(r.seconds < 0.5);
    served += r.status == 200 ? 1 : 0;
  }
  slowloris.join();
  CHECK(served > 5);
  CHECK(test::status_of(slow_answer) == 408);
  CHECK(error_reason(slow_answer) == "request_timeout");
  CHECK(std::chrono::steady_clock::now() - start < 3s);

  // Connected and silent past the deadline: closed without a word.
  CHECK(test::exchange_raw(port, "", 5000ms).empty());
}

TEST_CASE("network: over the connection limit new clients get 503, below it again they are served") {
  test::ScratchDir dir("connections");
  const DeviceRegistry registry = test::test_registry(1);
  SignalServiceOptions options = test::test_options(dir / "c.db");
  options.server.max_connections = 20;
  auto service = test::start_service(registry, options, false);
  const std::uint16_t port = service->port();
  net::io_context io;
  std::vector<net::ip::tcp::socket> idle;
  for (int i = 0; i < 20; ++i) {
    idle.emplace_back(io);
    idle.back().connect({net::ip::make_address("127.0.0.1"), port});
  }
  // The server counts a connection once it accepted it; give it a moment.
  for (int i = 0; i < 100 && service->metrics().open_connections() < 20; ++i) std::this_thread::sleep_for(10ms);
  const std::string raw = test::exchange_raw(port, "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n");
  CHECK(test::status_of(raw) == 503);
  CHECK(error_reason(raw) == "too_many_connections");
  idle.clear();
  for (int i = 0; i < 100 && service->metrics().open_connections() > 0; ++i) std::this_thread::sleep_for(10ms);
  CHECK(healthz(port).status == 200);
}

TEST_CASE("network: two services in one process, each with its own port, database and devices") {
  test::ScratchDir dir("two-services");
  const DeviceRegistry first_devices = test::test_registry(1);
  const DeviceRegistry second_devices({{"other-01", "second-service-token-1", "carol"}});
  auto first = test::start_service(first_devices, test::test_options(dir / "a.db"), false);
  auto second = test::start_service(second_devices, test::test_options(dir / "b.db"), false);
  REQUIRE(first->port() != second->port());
  ReadingsClient to_first({"127.0.0.1", first->port(), ""}, 2000ms);
  ReadingsClient to_second({"127.0.0.1", second->port(), ""}, 2000ms);
  CHECK(to_first.post("/v1/readings", reading_json("wb-00", 0), first_devices.devices()[0].token).status == 200);
  CHECK(to_second.post("/v1/readings", reading_json("other-01", 0), "second-service-token-1").status == 200);
  // Each knows only its own devices.
  CHECK(to_first.post("/v1/readings", reading_json("other-01", 1), "second-service-token-1").status == 401);
  first->stop();
  CHECK(to_second.post("/v1/readings", reading_json("other-01", 1), "second-service-token-1").status == 200);
  CHECK(second->counters().stored == 2);
  CHECK(first->counters().stored == 1);
  CHECK(to_first.get("/healthz").status < 0);  // stopped: a transport error
}
