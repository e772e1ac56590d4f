#include "perception/service/readings_client.h"

#include <optional>
#include <stdexcept>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http/read.hpp>
#include <boost/beast/http/string_body.hpp>
#include <boost/beast/http/write.hpp>

namespace alplan::perception::service {
namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;

}  // namespace

HttpEndpoint parse_http_url(const std::string& url) {
  const std::string scheme = "http://";
  if (url.rfind(scheme, 0) != 0) throw std::invalid_argument("URL '" + url + "': expected http://host:port[/path]");
  const std::string rest = url.substr(scheme.size());
  const auto slash = rest.find('/');
  const std::string authority = rest.substr(0, slash);
  HttpEndpoint endpoint;
  endpoint.path = slash == std::string::npos ? "" : rest.substr(slash);
  const auto colon = authority.rfind(':');
  endpoint.host = authority.substr(0, colon);
  if (endpoint.host.empty()) throw std::invalid_argument("URL '" + url + "': no host");
  if (colon != std::string::npos) {
    const std::string port = authority.substr(colon + 1);
    std::size_t used = 0;
    unsigned long value = 0;
    try {
      value = std::stoul(port, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (port.empty() || used != port.size() || value == 0 || value > 65535) {
      throw std::invalid_argument("URL '" + url + "': port '" + port + "' is not 1-65535");
    }
    endpoint.port = static_cast<std::uint16_t>(value);
  }
  return endpoint;
}

struct ReadingsClient::Impl {
  HttpEndpoint endpoint;
  std::chrono::milliseconds timeout;
  net::io_context io;
  std::optional<beast::tcp_stream> stream;
  beast::flat_buffer buffer;

  // Runs the asynchronous operations started before it: Beast's deadlines
  // (expires_after) bind asynchronous operations only.
  void run() {
    io.restart();
    io.run();
  }

  HttpResult connect() {
    HttpResult failed;
    beast::error_code error;
    try {
      tcp::resolver resolver(io);
      const auto addresses = resolver.resolve(endpoint.host, std::to_string(endpoint.port));
      stream.emplace(io);
      stream->expires_after(timeout);
      stream->async_connect(addresses, [&error](beast::error_code e, const tcp::endpoint&) { error = e; });
      run();
    } catch (const boost::system::system_error& e) {
      error = e.code();
    }
    if (!error) {
      stream->socket().set_option(tcp::no_delay(true), error);
      buffer.clear();
      return failed;  // status 0: connected
    }
    stream.reset();
    failed.status = error == beast::error::timeout ? kTransportTimeout : kTransportConnectFailed;
    failed.error = "cannot connect to " + endpoint.host + ":" + std::to_string(endpoint.port) + ": " + error.message();
    return failed;
  }

  // One exchange on the current connection.
  HttpResult exchange(const http::request<http::string_body>& request) {
    HttpResult result;
    http::response_parser<http::string_body> parser;
    parser.body_limit(16 * 1024 * 1024);
    beast::error_code error;
    stream->expires_after(timeout);
    http::async_write(*stream, request, [&](beast::error_code write_error, std::size_t) {
      error = write_error;
      if (write_error) return;
      http::async_read(*stream, buffer, parser, [&error](beast::error_code read_error, std::size_t) { error = read_error; });
    });
    run();
    if (error) {
      stream.reset();
      result.status = error == beast::error::timeout ? kTransportTimeout : kTransportConnectionLost;
      result.error = "request to " + endpoint.host + ":" + std::to_string(endpoint.port) + " failed: " + error.message();
      return result;
    }
    stream->expires_never();
    result.status = static_cast<int>(parser.get().result_int());
    result.body = std::move(parser.get().body());
    if (!parser.get().keep_alive()) stream.reset();
    return result;
  }

  HttpResult send(const http::request<http::string_body>& request) {
    const auto start = std::chrono::steady_clock::now();
    const bool reused = stream.has_value();
    HttpResult result;
    if (!reused) result = connect();
    if (result.status == 0) {
      result = exchange(request);
      // A reused connection the server had closed: one fresh attempt.
      if (reused && result.status == kTransportConnectionLost) {
        result = connect();
        if (result.status == 0) result = exchange(request);
      }
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }

  http::request<http::string_body> request(http::verb verb, std::string_view path) const {
    http::request<http::string_body> r{verb, std::string(path), 11};
    r.set(http::field::host, endpoint.host + ":" + std::to_string(endpoint.port));
    r.set(http::field::user_agent, "alplan-wristband-simulator");
    r.keep_alive(true);
    return r;
  }
};

ReadingsClient::ReadingsClient(const HttpEndpoint& endpoint, std::chrono::milliseconds timeout)
    : impl_(std::make_unique<Impl>()) {
  impl_->endpoint = endpoint;
  impl_->timeout = timeout;
}

ReadingsClient::~ReadingsClient() = default;

HttpResult ReadingsClient::post(std::string_view path, std::string_view body, std::string_view token) {
  http::request<http::string_body> r = impl_->request(http::verb::post, path);
  r.set(http::field::content_type, "application/json");
  if (!token.empty()) r.set(http::field::authorization, "Bearer " + std::string(token));
  r.body() = std::string(body);
  r.prepare_payload();
  return impl_->send(r);
}

HttpResult ReadingsClient::get(std::string_view path) {
  http::request<http::string_body> r = impl_->request(http::verb::get, path);
  r.prepare_payload();
  return impl_->send(r);
}

}  // namespace alplan::perception::service
