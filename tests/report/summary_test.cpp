#include "report/summary.h"

#include <catch2/catch.hpp>

#include "tests/report/log_of.h"

#include <sstream>

using namespace alplan::report;

namespace {

using test::log_of;

}  // namespace

TEST_CASE("the summary counts goals, comforted seniors, windows, failures and repairs by strategy") {
  const EventLog log = log_of(
      R"J({"type":"observation","time":0,"what":"home","home":{"seniors":[{"name":"senior1"},{"name":"senior2"},{"name":"senior3"}]}})J" "\n"
      R"J({"type":"goal","time":1,"senior":"senior1","goal":"(cheerful senior1)","window_end":50})J" "\n"
      R"J({"type":"goal","time":2,"senior":"senior2","goal":"(calm senior2)","window_end":40})J" "\n"
      R"J({"type":"goal","time":60,"senior":"senior1","goal":"(calm senior1)","window_end":90})J" "\n"
      R"J({"type":"plan","time":1,"plan_id":1,"reason":"initial","steps":[]})J" "\n"
      R"J({"type":"failure","time":10,"robot":"robot1","foreseen":false})J" "\n"
      R"J({"type":"failure","time":20,"robot":"robot1","foreseen":true})J" "\n"
      R"J({"type":"failure","time":30})J" "\n"
      R"J({"type":"repair","time":10.5,"strategy":"substitute","repaired":true,"seconds":0.25,"plan_id":2})J" "\n"
      R"J({"type":"repair","time":20.5,"strategy":"replan","repaired":false,"seconds":1.5,"plan_id":null})J" "\n"
      R"J({"type":"repair","time":30.5,"strategy":"replan","repaired":true,"seconds":0.5,"plan_id":3})J" "\n"
      R"J({"type":"repair","time":31})J" "\n"
      R"J({"type":"comforted","time":45,"senior":"senior1","within_window":true})J" "\n"
      R"J({"type":"window_missed","time":40,"senior":"senior2"})J" "\n"
      R"J({"type":"comforted","time":95,"senior":"senior1","within_window":false})J" "\n"
      R"J({"type":"explanation","time":95,"why":"w","what":"x","how":"y"})J" "\n");
  const RunSummary s = summarize(log);
  CHECK(s.end_time == 95);
  CHECK(s.plans == 1);
  CHECK(s.seniors_with_goals == 2);
  CHECK(s.goals == 3);
  CHECK(s.comforted == 2);
  CHECK(s.within_window == 1);
  CHECK(s.windows_missed == 1);
  CHECK(s.failures == 3);
  CHECK(s.foreseen_failures == 1);
  CHECK(s.explanations == 1);
  REQUIRE(s.seniors.size() == 3);  // senior3, in the home but without events, is listed too
  CHECK(s.seniors[0].senior == "senior1");
  CHECK(s.seniors[0].goals == 2);
  CHECK(s.seniors[0].within_window == 1);
  CHECK(s.seniors[1].windows_missed == 1);
  CHECK(s.seniors[2].goals == 0);
  REQUIRE(s.repairs.size() == 3);
  CHECK(s.repairs[0].strategy == "(unnamed)");
  CHECK(s.repairs[1].strategy == "replan");
  CHECK(s.repairs[1].attempts == 2);
  CHECK(s.repairs[1].repaired == 1);
  CHECK(s.repairs[1].seconds == Approx(2.0));
  CHECK(s.repairs[2].strategy == "substitute");
  CHECK(s.repairs[2].repaired == 1);
}

TEST_CASE("the summary states each robot's lowest battery and whether it went below its reserve") {
  const EventLog log = log_of(
      R"J({"type":"action_end","time":10,"robot":"robot1","action":"(move robot1 a b)","battery":31.5})J" "\n"
      R"J({"type":"action_end","time":20,"robot":"robot2","action":"(move robot2 a b)","battery":18})J" "\n"
      R"J({"type":"action_end","time":25,"robot":"robot1","action":"(carry robot1 g a)"})J" "\n"
      R"J({"type":"battery","time":90,"robot":"robot1","level":40,"lowest":24,"reserve":20,"below_reserve":false})J" "\n"
      R"J({"type":"battery","time":90,"robot":"robot2","level":18,"lowest":17.5,"reserve":20,"below_reserve":true})J" "\n");
  const RunSummary s = summarize(log);
  REQUIRE(s.batteries.size() == 2);
  CHECK(s.batteries[0].robot == "robot1");
  CHECK(s.batteries[0].lowest == 24);
  CHECK(s.batteries[0].reserve == 20);
  CHECK_FALSE(s.batteries[0].below_reserve);
  CHECK(s.batteries[1].robot == "robot2");
  CHECK(s.batteries[1].lowest == 17.5);
  CHECK(s.batteries[1].below_reserve);
  // A log without batteries has none.
  const EventLog plain = log_of(R"J({"type":"action_end","time":10,"robot":"robot1","action":"(move robot1 a b)"})J" "\n");
  CHECK(summarize(plain).batteries.empty());
}

TEST_CASE("each senior's lateness and each robot's busy share, hour by hour") {
  const EventLog log = log_of(
      R"J({"type":"goal","time":1,"senior":"senior1","window_end":50})J" "\n"
      R"J({"type":"comforted","time":80,"senior":"senior1","window_end":50,"within_window":false})J" "\n"
      R"J({"type":"goal","time":100,"senior":"senior1","window_end":150})J" "\n"
      R"J({"type":"comforted","time":160,"senior":"senior1","window_end":150,"within_window":false})J" "\n"
      R"J({"type":"goal","time":100,"senior":"senior2","window_end":150})J" "\n"
      R"J({"type":"comforted","time":120,"senior":"senior2","window_end":150,"within_window":true})J" "\n"
      R"J({"type":"action_start","time":3000,"robot":"robot1","action":"(move robot1 a b)"})J" "\n"
      R"J({"type":"action_start","time":3100,"robot":"robot1","action":"(look robot1)"})J" "\n"
      R"J({"type":"action_end","time":3300,"robot":"robot1","action":"(look robot1)"})J" "\n"
      R"J({"type":"action_end","time":4200,"robot":"robot1","action":"(move robot1 a b)"})J" "\n"
      R"J({"type":"action_start","time":6000,"robot":"robot2","action":"(move robot2 a b)"})J" "\n"
      R"J({"type":"explanation","time":7200,"senior":"senior1, senior2","why":"w","what":"x","how":"y"})J" "\n");
  const RunSummary s = summarize(log);
  REQUIRE(s.seniors.size() == 2);  // the explanation's list is no senior of its own
  CHECK(s.seniors[0].late == 2);
  CHECK(s.seniors[0].lateness_total == Approx(40.0));  // 30 + 10
  CHECK(s.seniors[0].lateness_max == Approx(30.0));
  CHECK(s.seniors[1].late == 0);
  REQUIRE(s.robots.size() == 2);
  // robot1: 3000-4200, the look inside it counted once; 600 s in hour 0, 600 s in hour 1.
  CHECK(s.robots[0].busy_seconds == Approx(1200.0));
  REQUIRE(s.robots[0].busy_share_per_hour.size() == 2);
  CHECK(s.robots[0].busy_share_per_hour[0] == Approx(600.0 / 3600.0));
  CHECK(s.robots[0].busy_share_per_hour[1] == Approx(600.0 / 3600.0));
  // robot2's move never ended in the log: busy to its last event.
  CHECK(s.robots[1].busy_seconds == Approx(1200.0));
}
