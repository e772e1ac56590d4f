#include "perception/service/http_server.h"

#include <future>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/ssl/context.hpp>
#include <boost/asio/strand.hpp>
#include <openssl/ssl.h>

#include "perception/service/http_session.h"

namespace alplan::perception::service {
namespace detail {

bool expects_continue(const HttpRequest& request) {
  const auto expect = request.find(http::field::expect);
  if (expect == request.end()) return false;
  std::string value(expect->value());
  for (char& c : value) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return value == "100-continue";
}

}  // namespace detail

using namespace detail;

namespace {

// TLS 1.2 or newer with the certificate chain and key from the files.
std::unique_ptr<net::ssl::context> load_tls(const ServerOptions& o) {
  auto tls = std::make_unique<net::ssl::context>(net::ssl::context::tls_server);
  tls->set_options(net::ssl::context::default_workarounds | net::ssl::context::no_sslv2 |
                   net::ssl::context::no_sslv3 | net::ssl::context::no_tlsv1 | net::ssl::context::no_tlsv1_1 |
                   net::ssl::context::single_dh_use);
  SSL_CTX_set_min_proto_version(tls->native_handle(), TLS1_2_VERSION);
  const auto load = [](const std::string& file, const char* what, auto&& step) {
    try {
      step();
    } catch (const boost::system::system_error& e) {
      throw std::runtime_error("cannot load the TLS " + std::string(what) + " " + file + ": " + e.code().message());
    }
  };
  load(o.tls_certificate_file, "certificate", [&] { tls->use_certificate_chain_file(o.tls_certificate_file); });
  // OpenSSL checks here that the key belongs to the certificate ("key values mismatch").
  load(o.tls_key_file, "key", [&] { tls->use_private_key_file(o.tls_key_file, net::ssl::context::pem); });
  return tls;
}

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
      start_session(std::move(socket));
      accept();
    });
  }

  void start_session(tcp::socket socket) {
    beast::error_code ec;
    const tcp::endpoint peer = socket.remote_endpoint(ec);
    if (ec) return;  // gone already
    ConnectionLimiter::Ticket ticket = context.limiter.admit(peer.address().to_string());
    Refusal refusal = Refusal::None;
    if (context.metrics.open_connections() >= static_cast<std::int64_t>(context.options.max_connections)) {
      refusal = Refusal::TooManyConnections;
    } else if (!ticket) {
      refusal = Refusal::TooManyFromClient;
    }
    if (tls) {
      std::make_shared<Session<TlsStream>>(std::move(socket), context, std::move(ticket), *tls)->start(refusal);
    } else {
      std::make_shared<Session<PlainStream>>(std::move(socket), context, std::move(ticket))->start(refusal);
    }
  }

  net::thread_pool handler_pool;
  ServerContext context;
  std::unique_ptr<net::ssl::context> tls;  // null: plain HTTP
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
  if (!o.tls_certificate_file.empty() || !o.tls_key_file.empty()) s.tls = load_tls(o);
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
