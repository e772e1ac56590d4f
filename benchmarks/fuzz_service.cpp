// libFuzzer target for the signal service's request path: Beast's HTTP
// parser with the service's limits, then the request handler (routing,
// authentication, the reading JSON, the SQLite store). Properties checked on
// any input bytes: no crash, leak or undefined behaviour (the sanitizers),
// and always a well-formed answer: a 2xx, 4xx or 5xx status, and a JSON body
// with a non-empty "error" for every 4xx/5xx.
//
// The first byte chooses how the rest is read: odd, as the whole request;
// even, as the body of a POST /v1/readings with a valid device token, so the
// fuzzer reaches the JSON validation without having to guess the token.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <nlohmann/json.hpp>

#include "perception/service/raw_request.h"

namespace {

using namespace alplan::perception::service;

void require(bool condition) {
  if (!condition) std::abort();
}

constexpr const char* kToken = "fuzz-token-0123456789";

// The service's parts over an in-memory database, made once: libFuzzer
// calls the target millions of times in one process.
struct Harness {
  DeviceRegistry registry{{{"wb-07", kToken, "senior-07"}}};
  ReadingStore store{":memory:", Durability::Normal};
  StressEventQueue events{64};
  ReadingIngest ingest{store, nullptr, events, registry, 0};
  ServiceMetrics metrics;
  RequestHandler handler{registry, ingest, metrics, events, HandlerLimits{}};
};

void check_well_formed(const HttpResponse& response) {
  const unsigned status = response.result_int();
  require((status >= 200 && status < 300) || (status >= 400 && status < 600));
  if (status < 400) return;
  const nlohmann::json body = nlohmann::json::parse(response.body(), nullptr, false);
  require(body.is_object() && body.contains("error") && body["error"].is_string());
  require(!body["error"].get<std::string>().empty());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static Harness harness;  // see Harness: built once per fuzzing process
  if (size == 0) return 0;
  std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] % 2 == 0) {
    bytes = "POST /v1/readings HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nAuthorization: Bearer " +
            std::string(kToken) + "\r\nContent-Length: " + std::to_string(bytes.size()) + "\r\n\r\n" + bytes;
  }
  check_well_formed(respond_to_bytes(harness.handler, harness.metrics, bytes, ParseLimits{}));
  return 0;
}
