// One client cannot hold every connection slot: a limit per client address.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <nlohmann/json.hpp>

#include "perception/service/connection_limiter.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;
using namespace std::chrono_literals;
namespace net = boost::asio;

namespace {

// A connection from `local` (any 127.x address) to the service.
net::ip::tcp::socket connect_from(net::io_context& io, const std::string& local, std::uint16_t port) {
  net::ip::tcp::socket socket(io);
  socket.open(net::ip::tcp::v4());
  socket.bind({net::ip::make_address(local), 0});
  socket.connect({net::ip::make_address("127.0.0.1"), port});
  return socket;
}

}  // namespace

TEST_CASE("limits: the connection limiter counts per client and frees a slot with its ticket") {
  ConnectionLimiter limiter(2);
  auto a1 = limiter.admit("10.0.0.1");
  auto a2 = limiter.admit("10.0.0.1");
  CHECK(a1);
  CHECK(a2);
  CHECK_FALSE(limiter.admit("10.0.0.1"));
  CHECK(limiter.admit("10.0.0.2"));
  CHECK(limiter.held_by("10.0.0.1") == 2);
  { const auto moved = std::move(a1); }
  CHECK(limiter.held_by("10.0.0.1") == 1);
  CHECK(limiter.admit("10.0.0.1"));
  CHECK_THROWS_AS(ConnectionLimiter(0), std::invalid_argument);
}

TEST_CASE("limits: one client cannot hold every connection - another client is still served") {
  test::ScratchDir dir("per-client");
  const DeviceRegistry registry = test::test_registry(1);
  SignalServiceOptions options = test::test_options(dir / "c.db");
  options.server.max_connections = 20;
  options.server.max_connections_per_client = 4;
  auto service = test::start_service(registry, options, false);
  net::io_context io;
  std::vector<net::ip::tcp::socket> greedy;
  for (int i = 0; i < 4; ++i) greedy.push_back(connect_from(io, "127.0.0.1", service->port()));
  for (int i = 0; i < 100 && service->metrics().open_connections() < 4; ++i) std::this_thread::sleep_for(10ms);
  const std::string raw = test::exchange_raw(service->port(), "GET /healthz HTTP/1.1\r\nHost: x\r\n\r\n");
  CHECK(test::status_of(raw) == 503);
  CHECK(nlohmann::json::parse(test::body_of(raw))["reason"] == "too_many_connections_from_client");
  // Another address on the same machine is its own client.
  net::ip::tcp::socket other = connect_from(io, "127.0.0.2", service->port());
  const std::string request = "GET /healthz HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n";
  net::write(other, net::buffer(request));
  boost::system::error_code ec;
  std::string answer;
  char chunk[1024];
  while (!ec) answer.append(chunk, other.read_some(net::buffer(chunk), ec));
  CHECK(test::status_of(answer) == 200);
  greedy.clear();
  for (int i = 0; i < 100 && service->metrics().open_connections() > 0; ++i) std::this_thread::sleep_for(10ms);
  CHECK(test::status_of(test::exchange_raw(service->port(), request)) == 200);
}
