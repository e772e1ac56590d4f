// From the bytes that arrive on a connection to the response, the way the
// server does it (Beast's HTTP/1.1 parser with the service's limits, then
// the handler), but without a socket: for the fuzz and property tests, and
// shared with the server for what a parse error is answered with.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <boost/beast/core/error.hpp>

#include "perception/service/request_handler.h"

namespace alplan::perception::service {

struct ParseLimits {
  std::size_t max_header_bytes = 8 * 1024;
  std::size_t max_body_bytes = 64 * 1024;
};

// The response to a request the parser refused (the connection is closed
// after it): 413 body over the limit, 431 header over the limit, 400 for
// anything else malformed. Counts the rejection and the response.
HttpResponse parse_error_response(const boost::beast::error_code& error, ServiceMetrics& metrics);

// Parses `bytes` as one request and answers it. An incomplete request is a
// 400 ("the request ended early"), as a client that closed mid-request
// would be. Never throws.
HttpResponse respond_to_bytes(RequestHandler& handler, ServiceMetrics& metrics, std::string_view bytes,
                              const ParseLimits& limits);

}  // namespace alplan::perception::service
