#include "report/event_log.h"

#include <catch2/catch.hpp>

#include <sstream>

using namespace alplan::report;

namespace {

const char* kHome =
    R"J({"type":"observation","time":0,"what":"home","home":{"name":"h","rooms":[{"name":"kitchen1","x":3,"y":1},)J"
    R"J({"name":"corridor1","x":0,"y":1},{"name":"nowhere"}],"connections":[["corridor1","kitchen1"],["bad"]],)J"
    R"J("seniors":[{"name":"senior1","room":"kitchen1"}],"robots":[{"name":"robot1","room":"corridor1"}],)J"
    R"J("objects":[{"name":"glass_id05","type":"glass","room":"kitchen1"}]},"settings":{"seed":7}})J";

struct Read {
  ReadResult result;
  std::string warnings;
};

Read read(const std::string& text) {
  std::istringstream in(text);
  std::ostringstream warnings;
  ReadResult r = read_event_log(in, "run.jsonl", warnings);
  return {std::move(r), warnings.str()};
}

}  // namespace

TEST_CASE("the home observation gives rooms with coordinates, connections, who is where and the settings") {
  const Read r = read(std::string(kHome) + "\n");
  REQUIRE(r.result.log);
  REQUIRE(r.result.log->home);
  const Home& h = *r.result.log->home;
  REQUIRE(h.rooms.size() == 2);  // "nowhere" has no coordinates
  CHECK(h.rooms[0].name == "kitchen1");
  CHECK(h.rooms[0].x == 3.0);
  CHECK(h.connections.size() == 1);
  CHECK(h.seniors.at(0).room == "kitchen1");
  CHECK(h.robots.at(0).name == "robot1");
  CHECK(h.objects.at(0).type == "glass");
  CHECK(r.result.log->settings["seed"] == 7);
  CHECK(r.result.log->events.empty());
  CHECK(r.warnings.find("run.jsonl:1: warning: a room without a name or coordinates") != std::string::npos);
}

TEST_CASE("a line that is not JSON is reported with its number and the rest of the log is used") {
  const Read r = read(std::string(kHome) + "\n" +
                      R"J({"type":"stress","time":5,"senior":"senior1","stressed":true,"score":0.8})J" "\n"
                      R"J({"type":"stress","time":)J" "\n"
                      R"J({"type":"comforted","time":9,"senior":"senior1","within_window":true})J" "\n");
  REQUIRE(r.result.log);
  CHECK(r.result.log->events.size() == 2);
  CHECK(r.result.log->events[1].type == "comforted");
  CHECK(r.result.log->events[1].line == 4);
  CHECK(r.warnings.find("\nrun.jsonl:3: warning: not JSON: ") != std::string::npos);
  CHECK(r.warnings.find("[json.exception") == std::string::npos);
  CHECK(r.warnings.find("not JSON: parse error at column 25: syntax error") != std::string::npos);
}

TEST_CASE("a truncated last line, as a crashed run leaves it, is reported and the lines before it kept") {
  const Read r = read(std::string(kHome) + "\n" + R"J({"type":"goal","time":3,"senior":"senior1","goal":"(che)J");
  REQUIRE(r.result.log);
  CHECK(r.result.log->home);
  CHECK(r.result.log->events.empty());
  CHECK(r.warnings.find("\nrun.jsonl:2: warning: not JSON: ") != std::string::npos);
}

TEST_CASE("lines JSON but unusable are skipped and say why, blank lines and unknown fields are fine") {
  const Read r = read(R"J({"type":"stress","time":1,"senior":"s1","mood":"unknown fields are allowed"})J" "\n\n"
                      R"J([1,2])J" "\n"
                      R"J({"type":"teleport","time":2})J" "\n"
                      R"J({"type":"stress","senior":"s1"})J" "\n"
                      R"J({"type":"stress","time":3})J" "\n"
                      R"J({"type":"plan","time":4,"plan_id":"one"})J" "\n"
                      R"J({"type":"action_start","time":5,"robot":"robot1"})J" "\n"
                      R"J({"type":"failure","time":6,"robot":null})J" "\n");
  REQUIRE(r.result.log);
  REQUIRE(r.result.log->events.size() == 2);
  CHECK(r.result.log->events[1].robot.empty());  // null: no robot concerned
  CHECK_FALSE(r.result.log->home);
  CHECK(r.warnings.find("run.jsonl:3: warning: not a JSON object") != std::string::npos);
  CHECK(r.warnings.find("run.jsonl:4: warning: unknown event type 'teleport'") != std::string::npos);
  CHECK(r.warnings.find("run.jsonl:5: warning: no numeric \"time\"") != std::string::npos);
  CHECK(r.warnings.find("run.jsonl:6: warning: a \"stress\" event without \"senior\"") != std::string::npos);
  CHECK(r.warnings.find("run.jsonl:7: warning: a \"plan\" event without an integer \"plan_id\"") != std::string::npos);
  CHECK(r.warnings.find("run.jsonl:8: warning: a \"action_start\" event without \"action\"") != std::string::npos);
}

TEST_CASE("a log without one usable line, or a file that cannot be opened, is an error") {
  const Read empty = read("");
  CHECK_FALSE(empty.result.log);
  CHECK(empty.result.error == "run.jsonl: error: no usable event in the log (expected JSON Lines, one event a line)");
  const Read garbage = read("hello\nworld\n");
  CHECK_FALSE(garbage.result.log);
  CHECK(garbage.warnings.find("run.jsonl:2: warning: not JSON") != std::string::npos);
  std::ostringstream warnings;
  const ReadResult missing = read_event_log_file("/nonexistent/run.jsonl", warnings);
  CHECK_FALSE(missing.log);
  CHECK(missing.error == "/nonexistent/run.jsonl: error: cannot open the file");
}

TEST_CASE("optional payload fields fall back when missing, null or of another type") {
  const nlohmann::json j = {{"s", "x"}, {"n", 2.5}, {"i", 3}, {"b", true}, {"z", nullptr}};
  CHECK(text_field(j, "s") == "x");
  CHECK(text_field(j, "n", "-") == "-");
  CHECK(number_field(j, "z", 7) == 7);
  CHECK(number_field(j, "n") == 2.5);
  CHECK(optional_int(j, "i") == 3);
  CHECK_FALSE(optional_int(j, "n"));
  CHECK(bool_field(j, "b"));
  CHECK_FALSE(bool_field(j, "missing"));
  CHECK(text_field(nlohmann::json::array(), "s", "-") == "-");
}
