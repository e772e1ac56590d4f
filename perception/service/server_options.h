// How the HTTP server listens and serves (http_server.h): shared with its
// sessions (http_session.h), apart from both so that neither includes the
// other.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "perception/service/raw_request.h"
#include "perception/service/request_handler.h"

namespace alplan::perception::service {

struct ServerOptions {
  std::string bind_address = "127.0.0.1";
  std::uint16_t port = 0;  // 0: any free port (see HttpServer::port())
  std::size_t io_threads = 1;
  std::size_t handler_threads = 4;
  std::size_t max_connections = 1024;
  // One client address may hold at most this many of them (a stalled or
  // greedy client cannot take every slot); more get 503.
  std::size_t max_connections_per_client = 256;
  std::chrono::milliseconds request_timeout{10000};
  std::chrono::milliseconds write_timeout{10000};
  ParseLimits parse_limits{};
  Endpoints endpoints = Endpoints::All;
  // PEM files; both empty: plain HTTP. With them every connection starts
  // with a TLS (1.2 or newer) handshake, within request_timeout.
  std::string tls_certificate_file;
  std::string tls_key_file;
};

}  // namespace alplan::perception::service
