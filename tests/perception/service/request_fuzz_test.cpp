// Property: whatever bytes arrive, the service answers with a well-formed
// HTTP response (a status it means, a JSON body with an "error" for every
// 4xx/5xx) and keeps working. Thousands of random requests from a fixed
// seed: pure noise, valid requests with bytes flipped, cut or spliced, and
// structurally valid JSON of the wrong shape. The libFuzzer target
// (benchmarks/fuzz_service.cpp) explores the same function by coverage.
#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>

#include <nlohmann/json.hpp>

#include "perception/service/raw_request.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;
namespace http = boost::beast::http;

namespace {

const std::string kReading =
    R"({"device":"wb-00","boot":0,"seq":1,"t_ms":1700000030000,"window_ms":30000,"hr_bpm":72.3,"ibi_ms":830.0,)"
    R"("sdnn_ms":41.3,"rmssd_ms":35.9,"beats":36,"rejected_fraction":0.063,"motion":false})";

std::string request_text(const std::string& method, const std::string& target, const std::string& token,
                         const std::string& body) {
  return method + " " + target + " HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nAuthorization: Bearer " +
         token + "\r\nContent-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
}

class RequestMaker {
 public:
  RequestMaker(std::uint64_t seed, std::string token) : random_(seed), token_(std::move(token)) {}

  std::string next() {
    switch (pick(6)) {
      case 0: return noise(pick(300));
      case 1: return mutate(valid_request());
      case 2: return request_text(method(), target(), token_, mutate(kReading));
      case 3: return request_text("POST", "/v1/readings", token_, random_json(3).dump());
      case 4: return valid_request().substr(0, pick(static_cast<std::uint32_t>(valid_request().size())));
      default: return valid_request();
    }
  }

 private:
  std::uint32_t pick(std::uint32_t n) { return n == 0 ? 0 : static_cast<std::uint32_t>(random_() % n); }

  std::string valid_request() {
    std::string body = "[" + kReading;
    body.replace(body.find("\"seq\":1"), 7, "\"seq\":" + std::to_string(pick(50)));
    return request_text("POST", "/v1/readings", token_, body + "]");
  }

  std::string noise(std::uint32_t length) {
    std::string s(length, ' ');
    for (char& c : s) c = static_cast<char>(pick(256));
    return s;
  }

  std::string mutate(std::string s) {
    const std::uint32_t edits = 1 + pick(8);
    for (std::uint32_t i = 0; i < edits && !s.empty(); ++i) {
      const std::uint32_t at = pick(static_cast<std::uint32_t>(s.size()));
      switch (pick(4)) {
        case 0: s[at] = static_cast<char>(pick(256)); break;
        case 1: s.erase(at, 1 + pick(10)); break;
        case 2: s.insert(at, noise(1 + pick(10))); break;
        default: s.insert(at, s.substr(pick(static_cast<std::uint32_t>(s.size())), pick(40))); break;
      }
    }
    return s;
  }

  // JSON strings must be valid UTF-8 to be written at all.
  std::string printable(std::uint32_t length) {
    std::string s(length, ' ');
    for (char& c : s) c = static_cast<char>(0x20 + pick(95));
    return s;
  }

  std::string method() {
    const char* methods[] = {"GET", "POST", "PUT", "HEAD", "DELETE", "OPTIONS", "PATCH", "BREW"};
    return methods[pick(8)];
  }

  std::string target() {
    const char* targets[] = {"/v1/readings", "/healthz", "/metrics", "/", "/v1/readings?x=1", "*", "/../etc", "/%00"};
    return targets[pick(8)];
  }

  nlohmann::json random_json(int depth) {
    switch (depth <= 0 ? pick(4) : pick(6)) {
      case 0: return nullptr;
      case 1: return static_cast<std::int64_t>(random_()) >> pick(64);
      case 2: return std::ldexp(static_cast<double>(random_() % 1000000), static_cast<int>(pick(80)) - 40);
      case 3: return printable(pick(8));
      case 4: {
        nlohmann::json a = nlohmann::json::array();
        for (std::uint32_t i = pick(14); i > 0; --i) a.push_back(random_json(depth - 1));
        return a;
      }
      default: {
        nlohmann::json o = nlohmann::json::parse(kReading);
        for (std::uint32_t i = pick(3); i > 0; --i) o[o.begin().key()] = random_json(depth - 1);
        const char* keys[] = {"device", "boot", "seq", "t_ms", "hr_bpm", "beats", "motion", "extra"};
        for (std::uint32_t i = pick(3); i > 0; --i) o[keys[pick(8)]] = random_json(depth - 1);
        if (pick(4) == 0) o.erase(keys[pick(8)]);
        return o;
      }
    }
  }

  std::mt19937_64 random_;
  std::string token_;
};

void check_well_formed(const HttpResponse& response) {
  const unsigned status = response.result_int();
  REQUIRE(((status >= 200 && status < 300) || (status >= 400 && status < 600)));
  REQUIRE(response.has_content_length());
  // A HEAD answer carries the GET's length and no body.
  const bool head = status == 200 && response.body().empty();
  if (!head) REQUIRE(response[http::field::content_length] == std::to_string(response.body().size()));
  if (status >= 400) {
    const nlohmann::json body = nlohmann::json::parse(response.body());
    REQUIRE(body["error"].is_string());
    REQUIRE_FALSE(body["error"].get<std::string>().empty());
  }
}

}  // namespace

TEST_CASE("fuzz: 20000 random requests through parser and handler, always a well-formed answer") {
  test::ScratchDir dir("fuzz");
  const DeviceRegistry registry = test::test_registry(1);
  ReadingStore store(dir / "f.db", Durability::Normal);
  StressEventQueue events(16);
  ReadingIngest ingest(store, nullptr, events, registry, 0);
  ServiceMetrics metrics;
  RequestHandler handler(registry, ingest, metrics, events, HandlerLimits{});
  RequestMaker maker(20240607, registry.devices()[0].token);
  std::map<unsigned, int> statuses;
  for (int i = 0; i < 20000; ++i) {
    const std::string bytes = maker.next();
    const HttpResponse response = respond_to_bytes(handler, metrics, bytes, ParseLimits{});
    check_well_formed(response);
    statuses[response.result_int()] += 1;
  }
  // The mix reached every layer: parser refusals, JSON refusals, acceptances.
  CHECK(statuses[200] > 1000);
  CHECK(statuses[400] > 1000);
  CHECK(statuses[401] + statuses[403] + statuses[404] + statuses[405] > 100);
  CHECK(statuses.count(500) == 0);
  // Edge cases the fuzzers found: nothing at all (Beast asserts on an EOF
  // before any byte), a number beyond double.
  CHECK(respond_to_bytes(handler, metrics, "", ParseLimits{}).result_int() == 400);
  const std::string huge = request_text("POST", "/v1/readings", registry.devices()[0].token, "[1e999]");
  CHECK(respond_to_bytes(handler, metrics, huge, ParseLimits{}).result_int() == 400);
  // And the service still stores a good reading afterwards.
  const std::string good = request_text("POST", "/v1/readings", registry.devices()[0].token, kReading);
  CHECK(respond_to_bytes(handler, metrics, good, ParseLimits{}).result_int() == 200);
}
