// A blocking HTTP/1.1 client for the service, as a wristband uses it: one
// keep-alive connection, POST a body with a bearer token, get the status and
// body back. Transport failures come back as negative statuses, like the
// Arduino HTTPClient's (so firmware::classify_upload_status() treats them as
// the board does): -1 could not connect, -5 connection lost, -11 timeout.
//
// A keep-alive connection the server has closed meanwhile (idle timeout) is
// only found out when it is used; then the request is sent once more on a
// new connection before giving up, as browsers and curl do.
//
// https:// URLs are spoken over TLS 1.2+, checking the server's certificate
// against a CA file (the board's ALPLAN_SERVICE_CA_PEM; the system's CAs
// when none is given) and the URL's host against the certificate's names,
// as the board's WiFiClientSecure does. A failed check is a failed connect.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace alplan::perception::service {

struct HttpEndpoint {
  std::string host;
  std::uint16_t port = 80;
  std::string path;  // "/v1/readings"; empty when the URL had none
  bool tls = false;  // https
};

// "http://host:port[/path]" or "https://host[:port][/path]" (port 443 by
// default). Throws std::invalid_argument naming the URL for anything else.
HttpEndpoint parse_http_url(const std::string& url);

inline constexpr int kTransportConnectFailed = -1;
inline constexpr int kTransportConnectionLost = -5;
inline constexpr int kTransportTimeout = -11;

struct HttpResult {
  int status = 0;       // HTTP status, or a negative transport error
  std::string body;
  std::string error;    // what went wrong, for a negative status
  double seconds = 0.0; // from sending the request to the whole response
};

class ReadingsClient {
 public:
  // `ca_file`: PEM certificates to trust for https (empty: the system's).
  // Throws std::runtime_error naming the file when it cannot be loaded.
  ReadingsClient(const HttpEndpoint& endpoint, std::chrono::milliseconds timeout, const std::string& ca_file = "");
  ~ReadingsClient();
  ReadingsClient(const ReadingsClient&) = delete;
  ReadingsClient& operator=(const ReadingsClient&) = delete;

  // POST `body` as application/json with "Authorization: Bearer <token>"
  // (no header when the token is empty).
  HttpResult post(std::string_view path, std::string_view body, std::string_view token);
  HttpResult get(std::string_view path);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace alplan::perception::service
