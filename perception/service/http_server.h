// The network side of the service: HTTP/1.1 over TCP with Boost.Beast,
// keep-alive, and the limits that keep one client from hurting the others.
//
//  - A request (header and body, from the moment the server starts waiting
//    for it) must arrive within request_timeout, whatever the client's pace:
//    a slowloris that trickles bytes is answered 408 and disconnected when
//    it runs out; a keep-alive connection idle that long is closed silently.
//  - Bodies over max_body_bytes get 413 as soon as the header announces them
//    (or when the chunks exceed it); headers over max_header_bytes 431;
//    anything the parser refuses 400. The connection is closed after these.
//  - Over max_connections open connections, or over
//    max_connections_per_client from one address, a new one is answered 503
//    and closed (the wristband backs off and retries).
//  - With a certificate and key, HTTPS (TLS 1.2+); otherwise plain HTTP.
//  - Reading and writing run on `io_threads` threads that never block; the
//    handler (which waits for the database commit) runs on a separate pool of
//    `handler_threads`, so a slow commit stalls no socket. "Expect:
//    100-continue" is honoured.
//
// One object, no global state: several servers run in one process on
// different ports (tests do).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "perception/service/raw_request.h"
#include "perception/service/server_options.h"
#include "perception/service/request_handler.h"
#include "perception/service/service_metrics.h"

namespace alplan::perception::service {

// True for 127.0.0.0/8 and ::1; false for anything else, unparsable included.
bool is_loopback_address(const std::string& address);

class HttpServer {
 public:
  // The handler and metrics must outlive the server.
  HttpServer(RequestHandler& handler, ServiceMetrics& metrics, const ServerOptions& options);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  // Binds, listens and starts the threads. Throws std::runtime_error naming
  // the address when it cannot bind, or the file when the TLS certificate
  // or key cannot be loaded. A server starts once: after stop(),
  // make a new one (on the same port if wanted).
  void start();
  // The bound port (the chosen one when options.port was 0).
  std::uint16_t port() const;
  // Stops accepting, lets running handlers finish, closes every connection
  // and joins the threads. Idempotent.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace alplan::perception::service
