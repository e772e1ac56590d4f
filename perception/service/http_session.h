// One client connection of HttpServer (http_server.h), over plain TCP or
// TLS: (handshake,) read a request, hand it to the handler pool, write the
// response, repeat while keep-alive. Internal to http_server.cpp; a header
// only because the session is a template over the two kinds of stream.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>

#include <boost/asio/dispatch.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/ssl/context.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/stream_traits.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http/read.hpp>
#include <boost/beast/http/write.hpp>
#include <boost/beast/ssl/ssl_stream.hpp>

#include "perception/service/connection_limiter.h"
#include "perception/service/server_options.h"

namespace alplan::perception::service::detail {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;
using PlainStream = beast::tcp_stream;
using TlsStream = beast::ssl_stream<beast::tcp_stream>;

// What every connection of one server shares.
struct ServerContext {
  ServerContext(RequestHandler& h, ServiceMetrics& m, const ServerOptions& o, net::thread_pool& pool)
      : handler(h), metrics(m), options(o), handler_pool(pool), limiter(o.max_connections_per_client) {}

  RequestHandler& handler;
  ServiceMetrics& metrics;
  ServerOptions options;
  net::thread_pool& handler_pool;
  ConnectionLimiter limiter;
  // Set by stop(): requests still arriving get 503, connections close after
  // their response instead of waiting for another request.
  std::atomic<bool> stopping{false};
  // Requests handed to the handler pool whose response is not written yet;
  // stop() waits for them, so a committed batch's answer reaches its client.
  std::atomic<int> answers_owed{0};
};

bool expects_continue(const HttpRequest& request);

// Why a new connection is turned away; None: it is served.
enum class Refusal { None, TooManyConnections, TooManyFromClient };

template <class Stream>
class Session : public std::enable_shared_from_this<Session<Stream>> {
 public:
  static constexpr bool kTls = std::is_same_v<Stream, TlsStream>;

  // `stream_args`: the SSL context for TLS, nothing for plain TCP.
  template <class... StreamArgs>
  Session(tcp::socket socket, ServerContext& context, ConnectionLimiter::Ticket ticket, StreamArgs&... stream_args)
      : stream_(std::move(socket), stream_args...),
        deadline_(stream_.get_executor()),
        context_(context),
        ticket_(std::move(ticket)) {
    context_.metrics.connection_opened();
  }
  ~Session() { context_.metrics.connection_closed(); }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  // Serves the connection, or (after the TLS handshake) answers 503 and
  // closes it when `refusal` says so.
  void start(Refusal refusal) {
    net::dispatch(stream_.get_executor(), [self = this->shared_from_this(), refusal] {
      if constexpr (kTls) {
        self->handshake(refusal);
      } else {
        self->begin(refusal);
      }
    });
  }

 private:
  // The handshake is part of the first request's deadline: a client that
  // connects and says nothing holds no slot for long.
  void handshake(Refusal refusal) {
    arm_deadline(context_.options.request_timeout);
    stream_.async_handshake(net::ssl::stream_base::server,
                            [self = this->shared_from_this(), refusal](beast::error_code ec) {
                              self->deadline_.cancel();
                              if (ec) return self->close();  // not TLS, a bad certificate, a timeout
                              self->begin(refusal);
                            });
  }

  void begin(Refusal refusal) {
    if (refusal == Refusal::None) return read_request();
    context_.metrics.connection_refused();
    const bool whole = refusal == Refusal::TooManyConnections;
    const std::string reason = whole ? "too_many_connections" : "too_many_connections_from_client";
    context_.metrics.count_rejection(reason);
    context_.metrics.count_response(503);
    write(error_response(503, reason,
                         whole ? "the service has too many open connections"
                               : "this client holds " + std::to_string(context_.options.max_connections_per_client) +
                                     " connections, the most one client may"),
          true);
  }

  tcp::socket& socket() { return beast::get_lowest_layer(stream_).socket(); }

  void read_request() {
    parser_.emplace();
    parser_->header_limit(static_cast<std::uint32_t>(context_.options.parse_limits.max_header_bytes));
    parser_->body_limit(context_.options.parse_limits.max_body_bytes);
    arm_deadline(context_.options.request_timeout);
    http::async_read_header(stream_, buffer_, *parser_, [self = this->shared_from_this()](beast::error_code ec,
                                                                                          std::size_t) {
      self->on_header(ec);
    });
  }

  // The whole request, however slowly it comes, must fit in one deadline.
  void arm_deadline(std::chrono::milliseconds timeout) {
    timed_out_ = false;
    deadline_.expires_after(timeout);
    deadline_.async_wait([self = this->shared_from_this()](beast::error_code ec) {
      if (ec) return;  // cancelled: the request arrived in time
      self->timed_out_ = true;
      beast::error_code ignored;
      self->socket().cancel(ignored);
    });
  }

  void on_header(beast::error_code ec) {
    if (ec) return on_read_error(ec);
    if (expects_continue(parser_->get())) {
      net::async_write(stream_, net::buffer(kContinue, sizeof kContinue - 1),
                       [self = this->shared_from_this()](beast::error_code write_ec, std::size_t) {
                         if (write_ec) return self->close();
                         self->read_body();
                       });
      return;
    }
    read_body();
  }

  void read_body() {
    http::async_read(stream_, buffer_, *parser_,
                     [self = this->shared_from_this()](beast::error_code ec, std::size_t) { self->on_body(ec); });
  }

  void on_body(beast::error_code ec) {
    if (ec) return on_read_error(ec);
    deadline_.cancel();
    if (context_.stopping.load()) {
      context_.metrics.count_rejection("shutting_down");
      context_.metrics.count_response(503);
      return write(error_response(503, "shutting_down", "the service is stopping; retry later"), true);
    }
    context_.answers_owed.fetch_add(1);
    // The handler may wait for a commit: run it off the I/O threads.
    net::post(context_.handler_pool, [self = this->shared_from_this(), request = parser_->release()]() mutable {
      HttpResponse response = self->context_.handler.handle(request, self->context_.options.endpoints);
      net::post(self->stream_.get_executor(), [self, response = std::move(response)]() mutable {
        const bool close_after = !response.keep_alive() || self->context_.stopping.load();
        self->write(std::move(response), close_after, true);
      });
    });
  }

  void on_read_error(beast::error_code ec) {
    deadline_.cancel();
    if (ec == net::error::operation_aborted && timed_out_) {
      const bool started = buffer_.size() > 0 || parser_->got_some();
      if (!started) return close();  // an idle keep-alive connection: just close
      context_.metrics.count_rejection("request_timeout");
      context_.metrics.count_response(408);
      return write(error_response(408, "request_timeout",
                                  "request not complete within " +
                                      std::to_string(context_.options.request_timeout.count()) + " ms"),
                   true);
    }
    const bool parse_error = ec.category() == http::make_error_code(http::error::bad_target).category() &&
                             ec != http::error::end_of_stream && ec != http::error::partial_message;
    if (parse_error) return write(parse_error_response(ec, context_.metrics), true);
    close();  // the peer went away (or sent half a request and closed)
  }

  // `owed`: the answer to a request the handler took (stop() waits for it).
  void write(HttpResponse response, bool close_after, bool owed = false) {
    response_ = std::make_shared<HttpResponse>(std::move(response));
    beast::get_lowest_layer(stream_).expires_after(context_.options.write_timeout);
    http::async_write(stream_, *response_,
                      [self = this->shared_from_this(), close_after, owed](beast::error_code ec, std::size_t) {
                        beast::get_lowest_layer(self->stream_).expires_never();
                        self->response_.reset();
                        if (owed) self->context_.answers_owed.fetch_sub(1);
                        if (ec || close_after || self->context_.stopping.load()) return self->close();
                        self->read_request();
                      });
  }

  // No TLS close_notify: the HTTP framing (Content-Length) already tells the
  // client where the answer ends, and a peer that does not answer the
  // notify would hold the connection.
  void close() {
    deadline_.cancel();
    beast::error_code ignored;
    socket().shutdown(tcp::socket::shutdown_send, ignored);
    socket().close(ignored);
  }

  static constexpr char kContinue[] = "HTTP/1.1 100 Continue\r\n\r\n";

  Stream stream_;
  net::steady_timer deadline_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::shared_ptr<HttpResponse> response_;
  bool timed_out_ = false;
  ServerContext& context_;
  ConnectionLimiter::Ticket ticket_;
};

}  // namespace alplan::perception::service::detail
