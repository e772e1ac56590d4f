#include "perception/service/http_server.h"

#include <atomic>
#include <future>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/strand.hpp>
#include <boost/asio/thread_pool.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/http/read.hpp>
#include <boost/beast/http/write.hpp>

namespace alplan::perception::service {
namespace {

namespace beast = boost::beast;
namespace http = beast::http;
namespace net = boost::asio;
using tcp = net::ip::tcp;

bool expects_continue(const HttpRequest& request) {
  const auto expect = request.find(http::field::expect);
  if (expect == request.end()) return false;
  std::string value(expect->value());
  for (char& c : value) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return value == "100-continue";
}

// What every connection shares.
struct ServerContext {
  ServerContext(RequestHandler& h, ServiceMetrics& m, const ServerOptions& o, net::thread_pool& pool)
      : handler(h), metrics(m), options(o), handler_pool(pool) {}

  RequestHandler& handler;
  ServiceMetrics& metrics;
  ServerOptions options;
  net::thread_pool& handler_pool;
  // Set by stop(): requests still arriving get 503, connections close after
  // their response instead of waiting for another request.
  std::atomic<bool> stopping{false};
  // Requests handed to the handler pool whose response is not written yet;
  // stop() waits for them, so a committed batch's answer reaches its client.
  std::atomic<int> answers_owed{0};
};

// One client connection: read a request, hand it to the handler pool, write
// the response, repeat while keep-alive. Lives as long as an operation of it
// is pending (shared_from_this in every completion).
class Session : public std::enable_shared_from_this<Session> {
 public:
  Session(tcp::socket socket, ServerContext& context)
      : stream_(std::move(socket)), deadline_(stream_.get_executor()), context_(context) {
    context_.metrics.connection_opened();
  }
  ~Session() { context_.metrics.connection_closed(); }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  void start() {
    net::dispatch(stream_.get_executor(), [self = shared_from_this()] { self->read_request(); });
  }

  // Over the connection limit: say so and close.
  void refuse() {
    net::dispatch(stream_.get_executor(), [self = shared_from_this()] {
      self->context_.metrics.connection_refused();
      self->context_.metrics.count_rejection("too_many_connections");
      self->context_.metrics.count_response(503);
      self->write(error_response(503, "too_many_connections", "the service has too many open connections"), true);
    });
  }

 private:
  void read_request() {
    parser_.emplace();
    parser_->header_limit(static_cast<std::uint32_t>(context_.options.parse_limits.max_header_bytes));
    parser_->body_limit(context_.options.parse_limits.max_body_bytes);
    arm_deadline(context_.options.request_timeout);
    http::async_read_header(stream_, buffer_, *parser_,
                            [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_header(ec); });
  }

  // The whole request, however slowly it comes, must fit in one deadline.
  void arm_deadline(std::chrono::milliseconds timeout) {
    timed_out_ = false;
    deadline_.expires_after(timeout);
    deadline_.async_wait([self = shared_from_this()](beast::error_code ec) {
      if (ec) return;  // cancelled: the request arrived in time
      self->timed_out_ = true;
      beast::error_code ignored;
      self->stream_.socket().cancel(ignored);
    });
  }

  void on_header(beast::error_code ec) {
    if (ec) return on_read_error(ec);
    if (expects_continue(parser_->get())) {
      net::async_write(stream_, net::buffer(kContinue, sizeof kContinue - 1),
                       [self = shared_from_this()](beast::error_code write_ec, std::size_t) {
                         if (write_ec) return self->close();
                         self->read_body();
                       });
      return;
    }
    read_body();
  }

  void read_body() {
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code ec, std::size_t) { self->on_body(ec); });
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
    net::post(context_.handler_pool, [self = shared_from_this(), request = parser_->release()]() mutable {
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
    stream_.expires_after(context_.options.write_timeout);
    http::async_write(stream_, *response_,
                      [self = shared_from_this(), close_after, owed](beast::error_code ec, std::size_t) {
                        self->stream_.expires_never();
                        self->response_.reset();
                        if (owed) self->context_.answers_owed.fetch_sub(1);
                        if (ec || close_after || self->context_.stopping.load()) return self->close();
                        self->read_request();
                      });
  }

  void close() {
    deadline_.cancel();
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
    stream_.socket().close(ignored);
  }

  static constexpr char kContinue[] = "HTTP/1.1 100 Continue\r\n\r\n";

  beast::tcp_stream stream_;
  net::steady_timer deadline_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  std::shared_ptr<HttpResponse> response_;
  bool timed_out_ = false;
  ServerContext& context_;
};

}  // namespace

bool is_loopback_address(const std::string& address) {
  beast::error_code error;
  const net::ip::address parsed = net::ip::make_address(address, error);
  return !error && parsed.is_loopback();
}

struct HttpServer::Impl {
  Impl(RequestHandler& handler, ServiceMetrics& metrics, const ServerOptions& options)
      : handler_pool(options.handler_threads == 0 ? 1 : options.handler_threads),
        context(handler, metrics, options, handler_pool) {}

  void accept() {
    acceptor->async_accept(net::make_strand(*io), [this](beast::error_code ec, tcp::socket socket) {
      if (ec == net::error::operation_aborted) return;
      if (ec) {
        // Out of descriptors, say: try again shortly rather than spin or give up.
        retry_accept->expires_after(std::chrono::milliseconds(50));
        retry_accept->async_wait([this](beast::error_code wait_ec) {
          if (!wait_ec) accept();
        });
        return;
      }
      const bool full =
          context.metrics.open_connections() >= static_cast<std::int64_t>(context.options.max_connections);
      auto session = std::make_shared<Session>(std::move(socket), context);
      full ? session->refuse() : session->start();
      accept();
    });
  }

  net::thread_pool handler_pool;
  ServerContext context;
  std::unique_ptr<net::io_context> io;
  std::unique_ptr<tcp::acceptor> acceptor;
  std::unique_ptr<net::steady_timer> retry_accept;
  // Keeps the I/O threads running while stop() drains, when no socket
  // operation is pending (a session waits for its handler).
  std::optional<net::executor_work_guard<net::io_context::executor_type>> work;
  std::vector<std::thread> io_threads;
  std::uint16_t port = 0;
  bool running = false;
  bool stopped = false;
};

HttpServer::HttpServer(RequestHandler& handler, ServiceMetrics& metrics, const ServerOptions& options)
    : impl_(std::make_unique<Impl>(handler, metrics, options)) {}

HttpServer::~HttpServer() { stop(); }

void HttpServer::start() {
  Impl& s = *impl_;
  if (s.running) return;
  if (s.stopped) throw std::logic_error("an HttpServer starts once; make a new one to serve again");
  const ServerOptions& o = s.context.options;
  s.io = std::make_unique<net::io_context>(static_cast<int>(o.io_threads == 0 ? 1 : o.io_threads));
  const std::string where = o.bind_address + ":" + std::to_string(o.port);
  try {
    const tcp::endpoint endpoint(net::ip::make_address(o.bind_address), o.port);
    s.acceptor = std::make_unique<tcp::acceptor>(*s.io);
    s.acceptor->open(endpoint.protocol());
    // A restarted service binds its old port while old connections linger in TIME_WAIT.
    s.acceptor->set_option(net::socket_base::reuse_address(true));
    s.acceptor->bind(endpoint);
    s.acceptor->listen(net::socket_base::max_listen_connections);
    s.port = s.acceptor->local_endpoint().port();
    s.retry_accept = std::make_unique<net::steady_timer>(*s.io);
  } catch (const boost::system::system_error& e) {
    s.acceptor.reset();
    s.io.reset();
    throw std::runtime_error("cannot listen on " + where + ": " + e.code().message());
  }
  s.work.emplace(s.io->get_executor());
  s.accept();
  for (std::size_t i = 0; i < (o.io_threads == 0 ? 1 : o.io_threads); ++i) {
    s.io_threads.emplace_back([io = s.io.get()] { io->run(); });
  }
  s.running = true;
}

std::uint16_t HttpServer::port() const { return impl_->port; }

void HttpServer::stop() {
  Impl& s = *impl_;
  if (!s.running) return;
  s.running = false;
  s.stopped = true;
  s.context.stopping.store(true);
  // No new connections: the acceptor is closed on its own thread.
  std::promise<void> closed;
  net::post(*s.io, [&s, &closed] {
    beast::error_code ignored;
    s.acceptor->close(ignored);
    s.retry_accept->cancel();
    closed.set_value();
  });
  closed.get_future().wait();
  // Running handlers finish (their commits complete) while the I/O threads
  // still run, so their answers are written: a client whose batch was
  // committed hears so. A client that does not read its answer is given
  // up on after the write timeout.
  s.handler_pool.join();
  const auto give_up = std::chrono::steady_clock::now() + s.context.options.write_timeout;
  while (s.context.answers_owed.load() > 0 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  s.work.reset();
  s.io->stop();
  for (std::thread& t : s.io_threads) t.join();
  s.io_threads.clear();
  s.acceptor.reset();
  s.retry_accept.reset();
  s.io.reset();  // destroys the pending operations and with them the sessions and sockets
}

}  // namespace alplan::perception::service
