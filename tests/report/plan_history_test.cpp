#include "report/plan_history.h"

#include <catch2/catch.hpp>

#include "tests/report/log_of.h"

#include <algorithm>
#include <sstream>

using namespace alplan::report;

namespace {

using test::log_of;

const PlanStep& step(const PlanHistory& h, int plan, const std::string& action) {
  const auto it = std::find_if(h.steps.begin(), h.steps.end(),
                               [&](const PlanStep& s) { return s.plan_id == plan && s.action == action; });
  REQUIRE(it != h.steps.end());
  return *it;
}

// Plan 1 moves robot1 twice; plan 2 supersedes it at 15, after the first
// move started: the second move never ran.
const char* kSuperseded =
    R"J({"type":"plan","time":0,"plan_id":1,"reason":"initial","supersedes":null,"steps":[)J"
    R"J({"start":0,"duration":10,"action":"(move robot1 a b)","robot":"robot1"},)J"
    R"J({"start":10,"duration":10,"action":"(move robot1 b c)"}]})J" "\n"
    R"J({"type":"action_start","time":0,"robot":"robot1","action":"(move robot1 a b)","plan_id":1})J" "\n"
    R"J({"type":"action_end","time":10,"robot":"robot1","action":"(move robot1 a b)","plan_id":1})J" "\n"
    R"J({"type":"action_start","time":10.5,"robot":"robot1","action":"(move robot1 b d)"})J" "\n"
    R"J({"type":"plan","time":15,"plan_id":2,"reason":"repair","supersedes":1,"steps":[)J"
    R"J({"start":0,"duration":5,"action":"(move robot1 d b)","robot":"robot1"}]})J" "\n";

}  // namespace

TEST_CASE("steps of a superseded plan not started by then never ran, started ones ran") {
  const PlanHistory h = plan_history(log_of(kSuperseded));
  REQUIRE(h.plans.size() == 2);
  CHECK(h.plans[0].superseded_at == 15);
  CHECK_FALSE(h.plans[1].superseded_at);
  const PlanStep& first = step(h, 1, "(move robot1 a b)");
  CHECK(first.status == StepStatus::Ran);
  CHECK(first.started_at == 0);
  CHECK(first.ended_at == 10);
  const PlanStep& second = step(h, 1, "(move robot1 b c)");
  CHECK(second.status == StepStatus::NeverRan);
  CHECK(second.robot == "robot1");  // named by the action when the step does not say
  CHECK(step(h, 2, "(move robot1 d b)").status == StepStatus::NotStarted);
}

TEST_CASE("a plan whose steps start before it was made counts from its making") {
  const PlanHistory h = plan_history(log_of(kSuperseded));
  CHECK(step(h, 2, "(move robot1 d b)").start == 15);
  CHECK(step(h, 1, "(move robot1 b c)").start == 10);
}

TEST_CASE("an action_start without a plan_id belongs to the latest plan with that action") {
  const PlanHistory h = plan_history(log_of(
      R"J({"type":"plan","time":0,"plan_id":1,"steps":[{"start":0,"duration":1,"action":"(talk robot1 s)"}]})J" "\n"
      R"J({"type":"plan","time":5,"plan_id":2,"steps":[{"start":6,"duration":1,"action":"(talk robot1 s)"}]})J" "\n"
      R"J({"type":"action_start","time":6,"robot":"robot1","action":"(talk robot1 s)"})J" "\n"));
  CHECK(step(h, 1, "(talk robot1 s)").status == StepStatus::NotStarted);
  CHECK(step(h, 2, "(talk robot1 s)").status == StepStatus::Ran);
}

TEST_CASE("a robot's route is the moves it started, in time order, including moves no plan listed") {
  const auto routes = robot_routes(log_of(kSuperseded));
  REQUIRE(routes.count("robot1") == 1);
  const std::vector<Move>& moves = routes.at("robot1");
  REQUIRE(moves.size() == 2);
  CHECK(moves[0].from == "a");
  CHECK(moves[0].to == "b");
  CHECK(moves[1].to == "d");
  CHECK(moves[1].time == 10.5);
}

TEST_CASE("action terms split a PDDL action, anything else gives none") {
  CHECK(action_terms("(move robot1 a b)") == std::vector<std::string>{"move", "robot1", "a", "b"});
  CHECK(action_terms("move robot1").empty());
  CHECK(action_terms(")(").empty());
}
