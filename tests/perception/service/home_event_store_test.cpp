#include <catch2/catch.hpp>

#include <sys/stat.h>

#include "perception/service/home_event_store.h"
#include "perception/service/reading_store.h"
#include "service_fixture.h"

using namespace alplan;
using namespace alplan::perception::service;

TEST_CASE("the home's events go into the service's database beside its readings, kept private") {
  test::ScratchDir dir("home-events");
  const auto file = dir / "s.db";
  {
    ReadingStore readings(file);  // the service made the database first
    HomeEventStore events(file);
    events.insert({1.5, "stress", "senior1", "", R"({"stressed":true})"}, 1000);
    events.insert({7.0, "plan", "", "", R"({"plan_id":1})"}, 2000);
    events.insert({9.0, "action_start", "", "robot1", R"j({"action":"(carry robot1 glass kitchen1)"})j"}, 3000);
  }
  HomeEventStore reopened(file, Durability::Normal);
  const std::vector<HomeEventRow> rows = reopened.rows();
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].time == 1.5);
  CHECK(rows[0].type == "stress");
  CHECK(rows[0].senior == "senior1");
  CHECK(rows[0].robot.empty());
  CHECK(rows[0].payload_json == R"({"stressed":true})");
  CHECK(rows[1].senior.empty());
  CHECK(rows[2].robot == "robot1");
  // The readings' schema is untouched: the service opens it again.
  ReadingStore again(file);
  CHECK(again.count_readings() == 0);
  struct stat st {};
  REQUIRE(::stat(file.c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0600);
}

TEST_CASE("the home's events alone make a private database too") {
  test::ScratchDir dir("home-events-alone");
  const auto file = dir / "h.db";
  HomeEventStore events(file);
  events.insert({0.0, "observation", "", "", "{}"}, 1);
  CHECK(events.rows().size() == 1);
  struct stat st {};
  REQUIRE(::stat(file.c_str(), &st) == 0);
  CHECK((st.st_mode & 0777) == 0600);
}
