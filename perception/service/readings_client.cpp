#include "perception/service/readings_client.h"

#include <optional>
#include <stdexcept>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl/context.hpp>
#include <boost/asio/ssl/host_name_verification.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/ssl/ssl_stream.hpp>
#include <openssl/err.h>
#include <openssl/ssl.h>
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
  HttpEndpoint endpoint;
  std::string scheme = "http://";
  if (url.rfind("https://", 0) == 0) {
    scheme = "https://";
    endpoint.tls = true;
    endpoint.port = 443;
  } else if (url.rfind(scheme, 0) != 0) {
    throw std::invalid_argument("URL '" + url + "': expected http://host:port[/path]");
  }
  const std::string rest = url.substr(scheme.size());
  const auto slash = rest.find('/');
  const std::string authority = rest.substr(0, slash);
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
  std::unique_ptr<net::ssl::context> tls;  // for https
  std::optional<beast::tcp_stream> plain;
  std::optional<beast::ssl_stream<beast::tcp_stream>> secure;
  beast::flat_buffer buffer;

  bool connected() const { return plain.has_value() || secure.has_value(); }
  void drop() {
    plain.reset();
    secure.reset();
  }
  beast::tcp_stream& lowest() { return secure ? beast::get_lowest_layer(*secure) : *plain; }
  // Calls f with the stream requests go over.
  template <class F>
  void with_stream(F&& f) {
    if (secure) {
      f(*secure);
    } else {
      f(*plain);
    }
  }

  // Runs the asynchronous operations started before it: Beast's deadlines
  // (expires_after) bind asynchronous operations only.
  void run() {
    io.restart();
    io.run();
  }

  std::string where() const { return endpoint.host + ":" + std::to_string(endpoint.port); }

  // The TLS handshake on a connected socket, checking the certificate and
  // that it names the URL's host (or IP address).
  beast::error_code handshake() {
    secure.emplace(std::move(*plain), *tls);
    plain.reset();
    beast::error_code error;
    beast::error_code ip_error;
    net::ip::make_address(endpoint.host, ip_error);
    // SNI: a host name only (RFC 6066 forbids addresses there).
    // (SSL_set_tlsext_host_name spelled out: the macro casts in C style.)
    if (ip_error && SSL_ctrl(secure->native_handle(), SSL_CTRL_SET_TLSEXT_HOSTNAME, TLSEXT_NAMETYPE_host_name,
                             const_cast<char*>(endpoint.host.c_str())) != 1) {
      return beast::error_code(static_cast<int>(::ERR_get_error()), net::error::get_ssl_category());
    }
    secure->set_verify_mode(net::ssl::verify_peer);
    secure->set_verify_callback(net::ssl::host_name_verification(endpoint.host));
    beast::get_lowest_layer(*secure).expires_after(timeout);
    secure->async_handshake(net::ssl::stream_base::client, [&error](beast::error_code e) { error = e; });
    run();
    return error;
  }

  HttpResult connect() {
    HttpResult failed;
    beast::error_code error;
    try {
      tcp::resolver resolver(io);
      const auto addresses = resolver.resolve(endpoint.host, std::to_string(endpoint.port));
      plain.emplace(io);
      plain->expires_after(timeout);
      plain->async_connect(addresses, [&error](beast::error_code e, const tcp::endpoint&) { error = e; });
      run();
    } catch (const boost::system::system_error& e) {
      error = e.code();
    }
    if (!error) {
      plain->socket().set_option(tcp::no_delay(true), error);
      buffer.clear();
    }
    std::string what = "cannot connect to ";
    if (!error && endpoint.tls) {
      error = handshake();
      what = "TLS handshake with ";
    }
    if (!error) return failed;  // status 0: connected
    drop();
    failed.status = error == beast::error::timeout ? kTransportTimeout : kTransportConnectFailed;
    failed.error = what + where() + " failed: " + error.message();
    return failed;
  }

  // One exchange on the current connection.
  HttpResult exchange(const http::request<http::string_body>& request) {
    HttpResult result;
    http::response_parser<http::string_body> parser;
    parser.body_limit(16 * 1024 * 1024);
    beast::error_code error;
    lowest().expires_after(timeout);
    with_stream([&](auto& stream) {
      http::async_write(stream, request, [&](beast::error_code write_error, std::size_t) {
        error = write_error;
        if (write_error) return;
        http::async_read(stream, buffer, parser, [&error](beast::error_code read_error, std::size_t) { error = read_error; });
      });
    });
    run();
    if (error) {
      drop();
      result.status = error == beast::error::timeout ? kTransportTimeout : kTransportConnectionLost;
      result.error = "request to " + where() + " failed: " + error.message();
      return result;
    }
    lowest().expires_never();
    result.status = static_cast<int>(parser.get().result_int());
    result.body = std::move(parser.get().body());
    if (!parser.get().keep_alive()) drop();
    return result;
  }

  HttpResult send(const http::request<http::string_body>& request) {
    const auto start = std::chrono::steady_clock::now();
    const bool reused = connected();
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

ReadingsClient::ReadingsClient(const HttpEndpoint& endpoint, std::chrono::milliseconds timeout,
                               const std::string& ca_file)
    : impl_(std::make_unique<Impl>()) {
  impl_->endpoint = endpoint;
  impl_->timeout = timeout;
  if (!endpoint.tls) return;
  impl_->tls = std::make_unique<net::ssl::context>(net::ssl::context::tls_client);
  SSL_CTX_set_min_proto_version(impl_->tls->native_handle(), TLS1_2_VERSION);
  try {
    if (ca_file.empty()) {
      impl_->tls->set_default_verify_paths();
    } else {
      impl_->tls->load_verify_file(ca_file);
    }
  } catch (const boost::system::system_error& e) {
    throw std::runtime_error("cannot load the CA certificates " + (ca_file.empty() ? "of the system" : ca_file) +
                             ": " + e.code().message());
  }
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
