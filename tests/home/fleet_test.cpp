// The home as a fleet (issue 31): goals allocated to robots, several
// missions at once, robots that break down.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "home/event_log.h"
#include "home/goal_allocation.h"
#include "domains/emotion_goals.h"
#include "domains/mission_run.h"
#include "home/home_problem.h"
#include "home/home_run.h"
#include "home/robot_dispatch.h"
#include "repair/reformulation.h"
#include "pddl_parser/ast.h"
#include "tests/support/test_paths.h"

namespace alplan::home {
namespace {

const std::string kAssistedLiving = test::source_dir() + "/domains/assisted_living";

// A corridor a - b - c - d, each hop 10 s; a senior in each end room.
pddl::Problem corridor() {
  pddl::Problem p;
  const auto atom = [](const std::string& name, std::vector<std::string> args) {
    pddl::Atom a;
    a.name = name;
    for (std::string& x : args) {
      pddl::Term t;
      t.name = std::move(x);
      a.args.push_back(std::move(t));
    }
    return a;
  };
  const std::vector<std::string> rooms{"a", "b", "c", "d"};
  for (std::size_t i = 0; i + 1 < rooms.size(); ++i) {
    for (const auto& [from, to] : {std::pair{rooms[i], rooms[i + 1]}, std::pair{rooms[i + 1], rooms[i]}}) {
      p.init.push_back(atom("path", {from, to}));
      pddl::NumericFact f;
      f.function = atom("moving_time", {from, to});
      f.value = 10.0;
      p.numeric_init.push_back(f);
    }
  }
  p.init.push_back(atom("be", {"sa", "a"}));
  p.init.push_back(atom("be", {"sd", "d"}));
  return p;
}

// The first event of a type that matches.
template <typename Match>
std::optional<LogEvent> first(const std::vector<LogEvent>& events, const std::string& type, Match match) {
  for (const LogEvent& e : events) {
    if (e.type == type && match(e)) return e;
  }
  return std::nullopt;
}

// The robots of each plan's steps, by plan id.
std::map<int, std::set<std::string>> plan_robots(const std::vector<LogEvent>& events) {
  std::map<int, std::set<std::string>> robots;
  for (const LogEvent& e : events) {
    if (e.type != "plan") continue;
    for (const auto& step : e.payload.at("steps")) {
      if (!step.at("robot").get<std::string>().empty()) robots[e.payload.at("plan_id")].insert(step.at("robot"));
    }
  }
  return robots;
}

HomeSettings scripted(std::vector<ScriptedEpisode> script, double until) {
  HomeSettings s = default_home_settings(kAssistedLiving);
  s.until = until;
  s.script = std::move(script);
  s.failure_chance = 0.0;  // the failures these tests need are scripted
  s.breakdowns.clear();
  return s;
}

bool comforted(const std::vector<LogEvent>& events, const std::string& senior) {
  return first(events, "comforted", [&](const LogEvent& e) { return e.senior == senior; }).has_value();
}

}  // namespace

TEST_CASE("allocation: the nearest idle robot, the most urgent first, a busy robot when it is sooner", "[home][fleet]") {
  const TravelTimes travel(corridor());
  AllocationOptions options;
  options.now = 100.0;
  options.service_s = 60.0;
  // r1 in a, r2 in d: each senior gets the robot in their room.
  std::vector<RobotLoad> robots{{"r1", "a", 100.0, true}, {"r2", "d", 100.0, true}};
  std::vector<GoalRequest> goals{{"sd", 500.0, 1.0, {}}, {"sa", 500.0, 1.0, {}}};
  std::vector<Assignment> out = allocate_goals(travel, robots, goals, options);
  REQUIRE(out.size() == 2);
  std::map<std::string, std::string> robot_of;
  for (const Assignment& a : out) robot_of[goals[a.goal].senior] = a.robot;
  CHECK(robot_of["sa"] == "r1");
  CHECK(robot_of["sd"] == "r2");

  // One idle robot in b: the terrified senior (weight 3) in d is placed
  // first and gets it, though the sad one in a is nearer and listed first.
  robots = {{"r1", "b", 100.0, true}};
  goals = {{"sa", 400.0, 2.0, {}}, {"sd", 140.0, 3.0, {}}};
  out = allocate_goals(travel, robots, goals, options);
  REQUIRE(out.size() == 2);
  CHECK(goals[out[0].goal].senior == "sd");
  CHECK(out[0].arrival == Approx(120.0));
  CHECK(out[0].to_idle);
  CHECK(out[1].arrival == Approx(120.0 + 60.0 + 30.0));  // served after sd, from d

  // A busy robot free soon in d beats an idle one far away; a robot that
  // refused the goal is no candidate.
  robots = {{"busy", "d", 105.0, false}, {"idle", "a", 100.0, true}};
  goals = {{"sd", 1000.0, 1.0, {}}};
  out = allocate_goals(travel, robots, goals, options);
  REQUIRE(out.size() == 1);
  CHECK(out[0].robot == "busy");
  CHECK_FALSE(out[0].to_idle);
  goals[0].refused_by = {"busy"};
  out = allocate_goals(travel, robots, goals, options);
  REQUIRE(out.size() == 1);
  CHECK(out[0].robot == "idle");
  goals[0].refused_by = {"busy", "idle"};
  CHECK(allocate_goals(travel, robots, goals, options).empty());
}

TEST_CASE("two missions at once: a new goal goes to the idle robot while the other works", "[home][fleet]") {
  // senior7 sad at 2400, senior2 terrified at 2460 (the default home's
  // script): the second goal comes while the first robot is on its way.
  const HomeSettings s = scripted({{"senior7", 2400.0, "sad"}, {"senior2", 2460.0, "terrified"}}, 3000.0);
  EventLog log;
  const HomeSummary summary = run_home(s, log);
  const std::vector<LogEvent>& events = log.events();
  const auto robots = plan_robots(events);
  std::map<int, int> mission_of;  // plan id -> mission
  std::map<int, std::pair<double, double>> span;  // mission -> first, last action time
  for (const LogEvent& e : events) {
    if (e.type == "plan") mission_of[e.payload.at("plan_id")] = e.payload.at("mission");
    if (e.type != "action_start" && e.type != "action_end") continue;
    const int m = mission_of.at(e.payload.at("plan_id"));
    auto [it, fresh] = span.try_emplace(m, e.time, e.time);
    it->second.second = e.time;
  }
  REQUIRE(span.size() == 2);
  const auto& [first_span, second_span] = std::pair{span.begin()->second, std::next(span.begin())->second};
  CHECK(second_span.first < first_span.second);  // the second began before the first ended
  const auto second_plan = first(events, "plan", [](const LogEvent& e) { return e.payload.at("mission") == 2; });
  REQUIRE(second_plan);
  CHECK(second_plan->payload.at("reason") == "initial");  // its own mission, not a merge
  const auto first_plan = first(events, "plan", [](const LogEvent& e) { return e.payload.at("mission") == 1; });
  CHECK(robots.at(first_plan->payload.at("plan_id")) != robots.at(second_plan->payload.at("plan_id")));
  CHECK(comforted(events, "senior7"));
  CHECK(comforted(events, "senior2"));
  CHECK(summary.within_window == 2);
  CHECK(summary.robot_busy_s.size() == 2);
}

TEST_CASE("a broken-down robot's goal is served by another", "[home][fleet]") {
  HomeSettings s = scripted({{"senior1", 300.0, "terrified"}}, 1500.0);
  s.breakdowns = {{"robot1", 420.0}};
  EventLog log;
  run_home(s, log);
  const std::vector<LogEvent>& events = log.events();
  const auto robots = plan_robots(events);
  const auto plan = first(events, "plan", [](const LogEvent&) { return true; });
  REQUIRE(plan);
  REQUIRE(robots.at(plan->payload.at("plan_id")) == std::set<std::string>{"robot1"});
  const auto down = first(events, "robot_down", [](const LogEvent& e) { return e.robot == "robot1"; });
  REQUIRE(down);
  CHECK(down->time == Approx(420.0));
  const auto taken_over = first(events, "plan", [&](const LogEvent& e) { return e.time >= down->time; });
  REQUIRE(taken_over);
  CHECK(robots.at(taken_over->payload.at("plan_id")) == std::set<std::string>{"robot2"});
  const auto done = first(events, "comforted", [](const LogEvent& e) { return e.senior == "senior1"; });
  REQUIRE(done);
  CHECK(done->time > down->time);
  // robot1 never acts while it is down.
  CHECK_FALSE(first(events, "action_start", [&](const LogEvent& e) {
    return e.robot == "robot1" && e.time >= down->time && e.time < 420.0 + s.robot_repair_s;
  }));
}

TEST_CASE("a goal merged into the busy robot's plan, and an impossible goal leaving the others served", "[home][fleet]") {
  // robot2 out of service all along: robot1 alone.
  HomeSettings s = scripted({{"senior7", 2400.0, "sad"}, {"senior2", 2460.0, "sad"}}, 3300.0);
  s.breakdowns = {{"robot2", 0.0}};
  s.robot_repair_s = 10000.0;
  EventLog log;
  run_home(s, log);
  const auto merge = first(log.events(), "plan", [](const LogEvent& e) { return e.payload.at("reason") == "merge"; });
  REQUIRE(merge);
  CHECK(comforted(log.events(), "senior7"));
  CHECK(comforted(log.events(), "senior2"));

  // A terrified senior's window shorter than any trip. As a hard deadline
  // that goal has no plan, alone or merged, and the sad senior is served
  // all the same; as a preference (the default) it is served late.
  s.script = {{"senior1", 300.0, "terrified"}, {"senior3", 300.0, "sad"}};
  s.terrified_window_s = 15.0;
  s.until = 1500.0;
  s.soft_windows = false;
  EventLog hard;
  const HomeSummary dropped = run_home(s, hard);
  CHECK(comforted(hard.events(), "senior3"));
  CHECK_FALSE(comforted(hard.events(), "senior1"));
  CHECK(dropped.never_served >= 1);

  s.soft_windows = true;
  EventLog soft;
  const HomeSummary late = run_home(s, soft);
  CHECK(comforted(soft.events(), "senior3"));
  const auto served = first(soft.events(), "comforted", [](const LogEvent& e) { return e.senior == "senior1"; });
  REQUIRE(served);
  CHECK_FALSE(served->payload.at("within_window").get<bool>());
  const auto passed = first(soft.events(), "window_passed", [](const LogEvent& e) { return e.senior == "senior1"; });
  REQUIRE(passed);
  // Looked at again when the window passed: the reading confirms the goal
  // in course (or would supersede it), and no second goal is made for it.
  CHECK(first(soft.events(), "emotion", [&](const LogEvent& e) { return e.senior == "senior1" && e.time >= passed->time; }));
  const auto confirmed = first(soft.events(), "goal_confirmed", [](const LogEvent& e) { return e.senior == "senior1"; });
  REQUIRE(confirmed);
  CHECK(confirmed->time < served->time);
  CHECK(std::count_if(soft.events().begin(), soft.events().end(), [&](const LogEvent& e) {
          return e.type == "goal" && e.senior == "senior1" && e.time < served->time;
        }) == 1);
  CHECK(late.never_served == 0);
  CHECK(late.weighted_lateness >= s.terrified_weight * (served->time - served->payload.at("window_end").get<double>()));
}

TEST_CASE("a device answers at once, in the same plan as the robot's remedy", "[home][fleet]") {
  // The default home's speaker in senior1's bedroom.
  const HomeSettings s = scripted({{"senior1", 300.0, "terrified"}}, 900.0);
  REQUIRE_FALSE(s.devices.empty());
  EventLog log;
  run_home(s, log);
  const auto plan = first(log.events(), "plan", [](const LogEvent&) { return true; });
  REQUIRE(plan);
  bool device_step = false, robot_step = false;
  for (const auto& step : plan->payload.at("steps")) {
    if (step.value("device", "") == "speaker1") {
      device_step = true;
      CHECK(step.at("duration").get<double>() == 0.0);
      CHECK(step.at("start").get<double>() == Approx(plan->time).margin(0.01));  // at once
      CHECK(step.at("action").get<std::string>().rfind("(play_calming_music speaker1 senior1", 0) == 0);
    }
    robot_step = robot_step || step.at("robot") == "robot1" || step.at("robot") == "robot2";
  }
  CHECK(device_step);
  CHECK(robot_step);
  CHECK(first(log.events(), "action_start", [](const LogEvent& e) { return e.payload.value("device", "") == "speaker1"; }));
  CHECK(first(log.events(), "explanation", [](const LogEvent& e) {
    return e.payload.at("how").get<std::string>().find("speaker1") != std::string::npos;
  }));
  CHECK(comforted(log.events(), "senior1"));
}

TEST_CASE("looked at again when the window passes, a senior whose face says otherwise gets the goal it calls for", "[home][fleet]") {
  // A face reader right 40% of the time and windows no robot can meet:
  // seed 6 reads senior1 again when the window passes and reads another
  // emotion, so the new goal supersedes the one in course.
  HomeSettings s = scripted({{"senior1", 300.0, "terrified"}}, 1500.0);
  s.terrified_window_s = 15.0;
  s.other_window_s = 15.0;
  s.seniors.face_accuracy = 0.4;
  s.seed = 6;
  EventLog log;
  const HomeSummary summary = run_home(s, log);
  const std::vector<LogEvent>& events = log.events();
  CHECK(summary.superseded >= 1);
  const auto successor = first(events, "goal", [](const LogEvent& e) { return e.payload.contains("supersedes"); });
  REQUIRE(successor);
  const std::string old_goal = successor->payload.at("supersedes");
  CHECK(old_goal != successor->payload.at("goal").get<std::string>());
  const auto retired = first(events, "goal_superseded", [&](const LogEvent& e) { return e.time >= successor->time; });
  REQUIRE(retired);
  CHECK(retired->payload.at("goal") == old_goal);
  // The goal it replaced was looked at again after its window passed, and is
  // not settled afterwards unless a later look calls for it anew.
  CHECK(first(events, "window_passed", [&](const LogEvent& e) { return e.payload.at("goal") == old_goal && e.time <= successor->time; }));
  const auto anew = first(events, "goal", [&](const LogEvent& e) { return e.time > retired->time && e.payload.at("goal") == old_goal; });
  const auto settled = first(events, "comforted", [&](const LogEvent& e) { return e.time > retired->time && e.payload.at("goal") == old_goal; });
  if (settled) {
    REQUIRE(anew);
    CHECK(anew->time <= settled->time);
  }
}

TEST_CASE("windows as preferences: the planner serves first the senior whose window weighs more", "[home][fleet]") {
  // robot1 alone in bedroom1; senior2 terrified in bedroom2 (water from the
  // kitchen: about 300 s), senior7 sad in the library (the guitar from the
  // music room). Windows of 340 and 400 s: whoever is served second is late,
  // so which is served first says which window weighs more.
  const domains::LoadedHome home = domains::load_home_files(
      kAssistedLiving + "/domain.pddl", kAssistedLiving + "/home.pddl", kAssistedLiving + "/types.ttl");
  pddl::Problem base = with_robots_only(*home.files.problem, {"robot1", "robot2"}, {"robot1"});
  for (const char* fact : {"terrified senior2", "hydration_time senior2", "sad senior7", "comfort_time senior7"}) {
    const std::string text(fact);
    base.init.push_back(domains::senior_atom(text.substr(0, text.find(' ')), text.substr(text.find(' ') + 1)));
  }
  PerceivedGoal terrified, sad;
  terrified.senior = "senior2";
  terrified.emotion = "terrified";
  terrified.goal = domains::senior_condition("soothed", "senior2");
  terrified.window_end = 340.0;
  sad.senior = "senior7";
  sad.emotion = "sad";
  sad.goal = domains::senior_condition("cheerful", "senior7");
  sad.window_end = 400.0;
  pddl::Condition both;
  both.kind = pddl::Condition::Kind::And;
  both.children = {terrified.goal, sad.goal};
  base.goal = both;
  // The order the plan hands things over in.
  const auto first_served = [&](const HomeSettings& settings) {
    pddl::Problem problem = base;
    prefer_windows(problem, base.metric, {terrified, sad}, 0.0, settings);
    REQUIRE(problem.constraints);
    const repair::PlanningOutcome planned =
        repair::plan_in_process(home.domain, problem, 0.0, home_planner_options(settings));
    REQUIRE(planned.plan);
    for (const repair::ScheduledAction& step : planned.plan->steps) {
      if (step.name.find("senior2") != std::string::npos && step.name.rfind("(give", 0) == 0) return std::string("senior2");
      if (step.name.find("senior7") != std::string::npos &&
          (step.name.rfind("(give", 0) == 0 || step.name.rfind("(suggest", 0) == 0)) return std::string("senior7");
    }
    return std::string();
  };
  HomeSettings settings;  // terrified 3, sad 2
  CHECK(first_served(settings) == "senior2");
  settings.terrified_weight = 1.0;
  settings.sad_weight = 5.0;
  CHECK(first_served(settings) == "senior7");
}

TEST_CASE("breakdowns at random: a Poisson process per robot, one breakdown at a time, the same for a seed", "[home][fleet]") {
  HomeSettings s = scripted({}, 36000.0);  // ten quiet hours: the robots idle
  s.breakdown_rate_per_hour = 2.0;
  s.robot_repair_s = 600.0;
  // A scripted breakdown late in the run: random ones still come before it,
  // and none while it lasts.
  s.breakdowns = {{"robot2", 30000.0}};
  const auto downs = [](const HomeSettings& settings) {
    EventLog log;
    const HomeSummary summary = run_home(settings, log);
    std::map<std::string, std::vector<double>> times;
    for (const LogEvent& e : log.events()) {
      if (e.type == "robot_down") times[e.robot].push_back(e.time);
    }
    std::size_t all = 0;
    for (const auto& [robot, t] : times) all += t.size();
    CHECK(summary.robots_down == all);
    return times;
  };
  const auto times = downs(s);
  REQUIRE(times.size() == 2);  // both robots of the default home
  CHECK(std::count_if(times.at("robot2").begin(), times.at("robot2").end(),
                      [](double t) { return t >= 30000.0 && t <= 30000.0 + 5.0; }) == 1);  // heard at the next step
  CHECK(std::count_if(times.at("robot2").begin(), times.at("robot2").end(), [](double t) { return t < 30000.0; }) >= 5);
  for (const auto& [robot, t] : times) {
    // A renewal process with dead time: 2 an hour, out 1/6 h each, gives
    // 2 / (1 + 2/6) = 1.5 an hour, 15 in ten hours; a rate read per second
    // or per day would give about 60 or under 1.
    CHECK(t.size() >= 7);
    CHECK(t.size() <= 25);
    for (std::size_t i = 1; i < t.size(); ++i) CHECK(t[i] - t[i - 1] >= s.robot_repair_s - 5.0);  // the home's step
  }
  CHECK(downs(s) == times);
  HomeSettings none = s;
  none.breakdown_rate_per_hour = 0.0;
  none.breakdowns.clear();
  CHECK(downs(none).empty());
}

}  // namespace alplan::home
