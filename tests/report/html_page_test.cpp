#include "report/html_page.h"

#include <catch2/catch.hpp>

#include "tests/report/log_of.h"

#include <sstream>

#include "report/chart_specs.h"

using namespace alplan::report;

namespace {

using test::log_of;

const char* kLog =
    R"J({"type":"observation","time":0,"what":"home","home":{"name":"<b>home</b>","rooms":[{"name":"a","x":0,"y":0},{"name":"b","x":4,"y":2}],"connections":[["a","b"]]},"settings":{"seed":7}})J" "\n"
    R"J({"type":"plan","time":0,"plan_id":1,"reason":"initial","steps":[{"start":0,"duration":4,"action":"(move robot1 a b)"},{"start":4,"duration":4,"action":"(move robot1 b a)"}]})J" "\n"
    R"J({"type":"action_start","time":0,"robot":"robot1","action":"(move robot1 a b)","plan_id":1})J" "\n"
    R"J({"type":"failure","time":3,"robot":"robot1","action":"(move robot1 a b)","condition":"(free b)"})J" "\n"
    R"J({"type":"plan","time":3.5,"plan_id":2,"reason":"repair","supersedes":1,"steps":[]})J" "\n"
    R"J({"type":"stress","time":1,"senior":"senior1","stressed":true,"score":0.9})J" "\n"
    R"J({"type":"explanation","time":3.5,"senior":"senior1","why":"</script><script>alert(1)</script>","what":"a & b","how":"\"q\""})J" "\n";

}  // namespace

TEST_CASE("text from the log is escaped in the page, in HTML and inside the charts' script") {
  const std::string page = render_report_page(log_of(kLog), "run.jsonl", {"/*vega*/", "/*vega-lite*/", "/*embed*/"});
  CHECK(page.find("<b>home") == std::string::npos);
  CHECK(page.find("&lt;b&gt;home&lt;/b&gt;") != std::string::npos);
  CHECK(page.find("<script>alert(1)") == std::string::npos);
  CHECK(page.find("&lt;/script&gt;&lt;script&gt;alert(1)&lt;/script&gt;") != std::string::npos);
  CHECK(page.find("<td>a &amp; b</td><td>&quot;q&quot;</td>") != std::string::npos);
  CHECK(page.find("/*vega*/") < page.find("/*vega-lite*/"));
  CHECK(page.find("/*vega-lite*/") < page.find("/*embed*/"));
  for (const char* id : {"id=\"gantt\"", "id=\"map\"", "id=\"timeline\"", "id=\"summary\"", "id=\"explanations\""}) {
    CHECK(page.find(id) != std::string::npos);
  }
}

TEST_CASE("JSON and JavaScript inlined in a script element cannot close it") {
  CHECK(script_json({{"a", "</script>"}}) == R"J({"a":"\u003c/script>"})J");
  CHECK(script_safe("x='</SCRIPT>';y='</div>'") == R"J(x='<\/SCRIPT>';y='</div>')J");
  CHECK(html_escape("<a href='x'>&</a>") == "&lt;a href=&#39;x&#39;&gt;&amp;&lt;/a&gt;");
}

TEST_CASE("the Gantt spec greys superseded steps and marks failures, the map and timeline have their data") {
  const EventLog log = log_of(kLog);
  const nlohmann::json gantt = gantt_spec(log, plan_history(log));
  const nlohmann::json& bars = gantt["layer"][0]["data"]["values"];
  REQUIRE(bars.size() == 2);
  CHECK(bars[0]["colour"] == "plan 1 (initial)");
  CHECK(bars[1]["colour"] == "never ran (superseded)");
  CHECK(gantt["layer"].size() == 3);  // bars, the failure's rule and its point
  CHECK(gantt["layer"][1]["data"]["values"][0]["condition"] == "(free b)");
  const nlohmann::json map = map_spec(log);
  CHECK(map["layer"][0]["data"]["values"].size() == 1);  // the connection
  CHECK(map["layer"][1]["data"]["values"].size() == 2);  // robot1's route: a, then b
  CHECK(timeline_spec(log)["data"]["values"].size() == 1);
  CHECK(timeline_spec(log_of(R"J({"type":"plan","time":0,"plan_id":1})J")).is_null());
}

TEST_CASE("load_vega_libraries names the missing file and how to get it") {
  const VegaLibrariesResult r = load_vega_libraries("/nonexistent");
  CHECK_FALSE(r.libraries);
  CHECK(r.error.rfind("/nonexistent/vega.min.js: error: cannot read the charting library", 0) == 0);
  CHECK(r.error.find("scripts/fetch_vega") != std::string::npos);
}

TEST_CASE("the settings are a table a person reads, not JSON") {
  const EventLog log = test::log_of(
      R"J({"type":"observation","time":0,"what":"home","home":{"name":"h"},"settings":{"strategy":"substitute","failure_kinds":["sibling","moves"],"battery":false,"until":3600,"battery_options":{"capacity":100}}})J" "\n"
      R"J({"type":"explanation","time":5,"senior":"senior1, senior2","why":"w","what":"x","how":"y"})J" "\n");
  const std::string page = render_report_page(log, "run.jsonl", {"/*vega*/", "/*vega-lite*/", "/*embed*/"});
  CHECK(page.find("<table id=\"settings\">") != std::string::npos);
  CHECK(page.find("<th>failure_kinds</th><td>sibling; moves</td>") != std::string::npos);
  CHECK(page.find("<th>battery</th><td>no</td>") != std::string::npos);
  CHECK(page.find("<th>battery_options</th><td>capacity 100</td>") != std::string::npos);
  CHECK(page.find("[\"sibling\"") == std::string::npos);
  CHECK(page.find("<td>senior1, senior2</td>") != std::string::npos);
  CHECK(page.find("<table id=\"utilisation\">") != std::string::npos);
}
