// The service's answers to every class of request, called directly (no
// sockets): the stored/duplicate acknowledgement, and a 4xx with a JSON
// error naming the problem for each kind of bad input.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include "perception/service/request_handler.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;
namespace http = boost::beast::http;
using nlohmann::json;

namespace {

std::string reading_json(const std::string& device, std::uint32_t seq, std::uint32_t boot = 0) {
  return R"({"device":")" + device + R"(","boot":)" + std::to_string(boot) + R"(,"seq":)" + std::to_string(seq) +
         R"(,"t_ms":)" + std::to_string(1700000000000ULL + 5000ULL * seq) +
         R"(,"window_ms":30000,"hr_bpm":72.3,"ibi_ms":830.0,"sdnn_ms":41.3,"rmssd_ms":35.9,"beats":36,)"
         R"("rejected_fraction":0.063,"motion":false})";
}

std::string batch_json(const std::string& device, const std::vector<std::uint32_t>& seqs) {
  std::string body = "[";
  for (std::size_t i = 0; i < seqs.size(); ++i) body += (i ? "," : "") + reading_json(device, seqs[i]);
  return body + "]";
}

// Everything a handler needs, over a scratch database.
struct HandlerBench {
  test::ScratchDir dir{"handler"};
  DeviceRegistry registry = test::test_registry(3);
  ReadingStore store{dir / "h.db", Durability::Normal};
  StressEventQueue events{64};
  ReadingIngest ingest{store, nullptr, events, registry, 0};
  ServiceMetrics metrics;
  // Detailed: the health and metrics test checks the per-device lines too.
  RequestHandler handler{registry, ingest, metrics, events, HandlerLimits{64 * 1024, 12, kDefaultMaxClockSkewMs, true}};

  const std::string& token(std::size_t device) const { return registry.devices()[device].token; }

  HttpResponse post(const std::string& body, const std::string& authorization,
                    const std::string& content_type = "application/json", const std::string& target = "/v1/readings") {
    HttpRequest request{http::verb::post, target, 11};
    if (!authorization.empty()) request.set(http::field::authorization, authorization);
    if (!content_type.empty()) request.set(http::field::content_type, content_type);
    request.body() = body;
    request.prepare_payload();
    return handler.handle(request);
  }

  HttpResponse send(http::verb verb, const std::string& target) {
    HttpRequest request{verb, target, 11};
    request.prepare_payload();
    return handler.handle(request);
  }
};

// The status, and the JSON error's message; checks the error body's shape.
std::string error_of(const HttpResponse& response) {
  REQUIRE(response[http::field::content_type] == "application/json");
  const json body = json::parse(response.body());
  REQUIRE(body.is_object());
  REQUIRE(body["error"].is_string());
  REQUIRE(body["reason"].is_string());
  return body["error"].get<std::string>();
}

}  // namespace

TEST_CASE("handler: a reading and a batch are acknowledged, duplicates and out-of-order ones said so") {
  HandlerBench b;
  const HttpResponse first = b.post(reading_json("wb-00", 5), "Bearer " + b.token(0));
  REQUIRE(first.result_int() == 200);
  json answer = json::parse(first.body());
  CHECK(answer["stored"] == 1);
  CHECK(answer["duplicates"] == 0);
  CHECK(answer["results"][0] == json{{"boot", 0}, {"seq", 5}, {"status", "stored"}});

  // Out of order (3 before 5, 4 after), a re-sent 5, and 4 twice in one batch.
  const HttpResponse second = b.post(batch_json("wb-00", {3, 5, 4, 4}), "bearer   " + b.token(0) + "  ");
  REQUIRE(second.result_int() == 200);
  answer = json::parse(second.body());
  CHECK(answer["stored"] == 2);
  CHECK(answer["duplicates"] == 2);
  const std::vector<std::string> statuses = {"stored", "duplicate", "stored", "duplicate"};
  for (std::size_t i = 0; i < 4; ++i) CHECK(answer["results"][i]["status"] == statuses[i]);
  CHECK(answer["results"][2]["seq"] == 4);
  CHECK(b.store.count_readings() == 3);
  CHECK(b.ingest.missing_by_device().at("wb-00") == 3);  // 0, 1, 2
  CHECK(b.post(reading_json("wb-00", 6), "Bearer " + b.token(0), "application/json; charset=utf-8").result_int() == 200);
}

TEST_CASE("handler: bad bodies get 400 naming the problem, and nothing is stored") {
  HandlerBench b;
  const std::string auth = "Bearer " + b.token(0);
  struct Case {
    std::string body, reason, message;
  };
  const std::vector<Case> cases = {
      {"{\"device\":", "malformed_json", "malformed JSON: "},
      {"\x01\x02garbage", "malformed_json", "malformed JSON: "},
      {reading_json("wb-00", 1).replace(reading_json("wb-00", 1).find("\"seq\":1"), 7, "\"seq\":\"1\""),
       "invalid_reading", "reading.seq: expected an integer, got a string"},
      {reading_json("wb-00", 1).replace(reading_json("wb-00", 1).find(",\"motion\":false"), 15, ""),
       "invalid_reading", "reading: missing key 'motion'"},
      {"[]", "invalid_reading", "body: the array holds no readings"},
      {"[" + reading_json("wb-00", 1) + ",{}]", "invalid_reading", "readings[1]: missing key 'device'"},
      {"{\"a\":[[[[[[[[[[[[[[[[[[[[[[[[[]]]]]]]]]]]]]]]]]]]]]]]]]}", "invalid_reading", "reading: unknown key 'a'"},
  };
  for (const Case& c : cases) {
    INFO(c.body);
    const HttpResponse response = b.post(c.body, auth);
    CHECK(response.result_int() == 400);
    CHECK(error_of(response).find(c.message) != std::string::npos);
    CHECK(json::parse(response.body())["reason"] == c.reason);
  }
  CHECK(b.store.count_readings() == 0);
  CHECK(b.metrics.rejections().at("invalid_reading") == 5);
  CHECK(b.metrics.rejections().at("malformed_json") == 2);
}

TEST_CASE("handler: strangers and impostors are refused with 401 and 403") {
  HandlerBench b;
  const std::string body = reading_json("wb-00", 1);
  HttpResponse r = b.post(body, "");
  CHECK(r.result_int() == 401);
  CHECK(r[http::field::www_authenticate] == "Bearer");
  CHECK(error_of(r) == "missing Authorization: Bearer <device token>");
  r = b.post(body, "Basic d2ItMDA6c2VjcmV0");
  CHECK(r.result_int() == 401);
  CHECK(error_of(r) == "Authorization must be 'Bearer <device token>'");
  r = b.post(body, "Bearer " + b.token(0).substr(1));
  CHECK(r.result_int() == 401);
  CHECK(error_of(r) == "unknown device token");
  // A real device posting in another's name, or for a device nobody registered.
  r = b.post(body, "Bearer " + b.token(1));
  CHECK(r.result_int() == 403);
  CHECK(error_of(r) == "reading.device: 'wb-00' is not the device this token belongs to");
  r = b.post(batch_json("wb-01", {1, 2}).replace(batch_json("wb-01", {1, 2}).rfind("wb-01"), 5, "zz-99"),
             "Bearer " + b.token(1));
  CHECK(r.result_int() == 403);
  CHECK(error_of(r) == "readings[1].device: 'zz-99' is not the device this token belongs to");
  CHECK(b.store.count_readings() == 0);
}

TEST_CASE("handler: wrong media type 415, too large 413, unknown path 404, wrong method 405") {
  HandlerBench b;
  const std::string auth = "Bearer " + b.token(0);
  HttpResponse r = b.post(reading_json("wb-00", 1), auth, "text/plain");
  CHECK(r.result_int() == 415);
  CHECK(error_of(r) == "Content-Type must be application/json");
  r = b.post(reading_json("wb-00", 1), auth, "");
  CHECK(r.result_int() == 415);
  r = b.post(std::string(64 * 1024 + 1, ' '), auth);
  CHECK(r.result_int() == 413);
  CHECK(error_of(r) == "body of 65537 bytes is over the limit of 65536");
  r = b.post(reading_json("wb-00", 1), auth, "application/json", "/v1/reading");
  CHECK(r.result_int() == 404);
  CHECK(error_of(r).find("no such path") == 0);
  r = b.send(http::verb::get, "/v1/readings");
  CHECK(r.result_int() == 405);
  CHECK(r[http::field::allow] == "POST");
  r = b.send(http::verb::delete_, "/healthz");
  CHECK(r.result_int() == 405);
  CHECK(r[http::field::allow] == "GET, HEAD");
  CHECK(error_of(r) == "/healthz takes GET");
  CHECK(b.send(http::verb::get, "/").result_int() == 404);
}

TEST_CASE("handler: health and metrics") {
  HandlerBench b;
  b.post(batch_json("wb-00", {0, 1, 1, 3}), "Bearer " + b.token(0));
  b.post("nope", "Bearer " + b.token(0));
  b.post("nope", "");
  HttpResponse health = b.send(http::verb::get, "/healthz?verbose=1");
  REQUIRE(health.result_int() == 200);
  const json h = json::parse(health.body());
  CHECK(h["status"] == "ok");
  CHECK(h["devices"] == 3);
  CHECK(h["stored_since_start"] == 3);
  const HttpResponse head = b.send(http::verb::head, "/healthz");
  CHECK(head.result_int() == 200);
  CHECK(head.body().empty());

  const HttpResponse metrics = b.send(http::verb::get, "/metrics");
  REQUIRE(metrics.result_int() == 200);
  CHECK(std::string(metrics[http::field::content_type]).find("text/plain; version=0.0.4") == 0);
  const std::string& text = metrics.body();
  for (const std::string line :
       {"alplan_readings_stored_total 3", "alplan_readings_duplicate_total 1", "alplan_readings_missing{device=\"wb-00\"} 1",
        "alplan_requests_rejected_total{reason=\"malformed_json\"} 1",
        "alplan_requests_rejected_total{reason=\"unauthorized\"} 1", "alplan_http_responses_total{code=\"200\"} 3",
        "alplan_http_responses_total{code=\"400\"} 1", "alplan_http_responses_total{code=\"401\"} 1",
        "alplan_readings_request_seconds_count 1", "alplan_stress_events_total{state=\"stressed\"} 0",
        "# TYPE alplan_readings_request_seconds summary"}) {
    INFO(line);
    CHECK(text.find(line + "\n") != std::string::npos);
  }
  CHECK(text.find("alplan_readings_request_seconds{quantile=\"0.99\"} ") != std::string::npos);
}
