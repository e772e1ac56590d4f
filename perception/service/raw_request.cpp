#include "perception/service/raw_request.h"

#include <boost/asio/buffer.hpp>
#include <boost/beast/http/error.hpp>
#include <boost/beast/http/parser.hpp>

namespace alplan::perception::service {

namespace http = boost::beast::http;

HttpResponse parse_error_response(const boost::beast::error_code& error, ServiceMetrics& metrics) {
  HttpResponse response;
  if (error == http::error::body_limit) {
    metrics.count_rejection("body_too_large");
    response = error_response(413, "body_too_large", "request body over the service's limit");
  } else if (error == http::error::header_limit) {
    metrics.count_rejection("header_too_large");
    response = error_response(431, "header_too_large", "request header over the service's limit");
  } else {
    metrics.count_rejection("malformed_http");
    response = error_response(400, "malformed_http", "malformed HTTP request: " + error.message());
  }
  metrics.count_response(response.result_int());
  return response;
}

HttpResponse respond_to_bytes(RequestHandler& handler, ServiceMetrics& metrics, std::string_view bytes,
                              const ParseLimits& limits) {
  try {
    http::request_parser<http::string_body> parser;
    parser.header_limit(static_cast<std::uint32_t>(limits.max_header_bytes));
    parser.body_limit(limits.max_body_bytes);
    parser.eager(true);
    boost::beast::error_code error;
    std::size_t used = 0;
    // put() consumes what it can; loop as a socket read would feed it.
    while (used < bytes.size() && !parser.is_done()) {
      const std::size_t n = parser.put(boost::asio::buffer(bytes.data() + used, bytes.size() - used), error);
      if (error == http::error::need_more) break;
      if (error) return parse_error_response(error, metrics);
      if (n == 0) break;
      used += n;
    }
    error = {};
    // put_eof() asserts that something was parsed; nothing at all is a request that ended early too.
    if (!parser.is_done() && parser.got_some()) parser.put_eof(error);
    if (error || !parser.is_done()) {
      return parse_error_response(error ? error : make_error_code(http::error::partial_message), metrics);
    }
    return handler.handle(parser.release());
  } catch (const std::exception& e) {
    metrics.count_rejection("internal_error");
    metrics.count_response(500);
    return error_response(500, "internal_error", std::string("internal error: ") + e.what());
  }
}

}  // namespace alplan::perception::service
