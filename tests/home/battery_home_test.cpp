// The home with robot batteries (issue 15, `alplan home --battery`): the
// battery variant of the paper's domain plans a recharge when a robot needs
// one, a home's problem gains a dock and battery values, and a run keeps
// every robot's battery (the simulated world's, over the whole run) at or
// above its reserve, logs it and replays.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <sstream>

#include "domains/battery_home.h"
#include "domains/mission_run.h"
#include "domains/pddl_files.h"
#include "home/event_log.h"
#include "home/home_run.h"
#include "planner/formula_evaluation.h"
#include "repair/reformulation.h"
#include "tests/support/test_paths.h"

namespace alplan::home {
namespace {

const std::string kAssistedLiving = test::source_dir() + "/domains/assisted_living";
const std::string kBatteryDomain = kAssistedLiving + "/battery/domain.pddl";

double value_of(const pddl::Problem& p, const std::string& function, const std::string& robot) {
  for (const pddl::NumericFact& f : p.numeric_init) {
    if (f.function.name == function && f.function.args.size() == 1 && f.function.args[0].name == robot) return f.value;
  }
  FAIL("no value of (" << function << " " << robot << ")");
  return 0.0;
}

std::vector<std::string> docks(const pddl::Problem& p) {
  std::vector<std::string> out;
  for (const pddl::Atom& a : p.init) {
    if (a.name == "dock") out.push_back(a.args.at(0).name);
  }
  return out;
}

std::string plan_of(const pddl::Problem& problem, const pddl::Domain& domain) {
  PlannerOptions options;
  options.time_limit = 10.0;
  options.epsilon = 0.001;
  const repair::PlanningOutcome planned = repair::plan_in_process(domain, problem, 0.0, options);
  REQUIRE(planned.plan.has_value());
  return repair::plan_text(*planned.plan);
}

// The default home with batteries, low enough that senior1's water needs a
// recharge: 30 with a reserve of 20 is 200 s of moving, and the kitchen and
// back is 280 s from senior1's bedroom.
HomeSettings low_battery_run() {
  HomeSettings s = default_home_settings(kAssistedLiving);
  s.until = 900.0;
  s.script = {{"senior1", 300.0, "terrified"}, {"senior5", 330.0, "bored"}};
  s.battery = true;
  s.battery_options.initial = 30.0;
  return s;
}

std::size_t count(const std::vector<LogEvent>& events, const std::string& type) {
  return static_cast<std::size_t>(
      std::count_if(events.begin(), events.end(), [&](const LogEvent& e) { return e.type == type; }));
}

}  // namespace

TEST_CASE("a home gains the battery file's dock and values: the central room, the defaults",
          "[home][battery]") {
  const domains::LoadedFiles plain = domains::load_pddl(kBatteryDomain, kAssistedLiving + "/home.pddl");
  const domains::LoadedFiles file = domains::load_pddl(kBatteryDomain, kAssistedLiving + "/battery/home.pddl");
  CHECK(domains::central_location(*plain.problem) == "corridor2");
  pddl::Problem added = *plain.problem;
  domains::add_batteries(added, {});
  CHECK(docks(added) == std::vector<std::string>{"corridor2"});
  CHECK(docks(added) == docks(*file.problem));
  for (const char* robot : {"robot1", "robot2"}) {
    for (const char* f : {"battery", "capacity", "reserve", "drain_rate", "charge_rate"}) {
      CHECK(value_of(added, f, robot) == value_of(*file.problem, f, robot));
    }
  }
  // What a problem already says stands; only what it lacks is added.
  pddl::Problem again = *file.problem;
  domains::BatteryOptions other;
  other.initial = 50.0;
  domains::add_batteries(again, other);
  CHECK(again.numeric_init.size() == file.problem->numeric_init.size());
  CHECK(value_of(again, "battery", "robot1") == 100.0);
  domains::BatteryOptions wrong;
  wrong.reserve = 150.0;
  CHECK_THROWS_AS(domains::add_batteries(again, wrong), std::invalid_argument);
}

TEST_CASE("a robot's battery return level takes it from the farthest room to the dock above its reserve",
          "[home][battery]") {
  const domains::LoadedFiles file = domains::load_pddl(kBatteryDomain, kAssistedLiving + "/battery/home.pddl");
  // The farthest rooms from corridor2 are the bedrooms, 30 + 50 s away:
  // 80 s at 0.05 a second above the reserve of 20.
  const std::map<std::string, double> levels = domains::return_levels(*file.problem);
  CHECK(levels == std::map<std::string, double>{{"robot1", 24.0}, {"robot2", 24.0}});
  pddl::Problem hungry = *file.problem;
  for (pddl::NumericFact& f : hungry.numeric_init) {
    if (f.function.name == "drain_rate") f.value = 2.0;  // 160 + 20 > 100
  }
  CHECK_THROWS_AS(domains::return_levels(hungry), std::invalid_argument);
}

TEST_CASE("the battery domain plans a recharge when a robot cannot reach the senior without one",
          "[home][battery]") {
  const domains::LoadedHome home = domains::load_home_files(
      kBatteryDomain, test::data_dir() + "/home/battery-recharge.pddl", kAssistedLiving + "/types.ttl");
  const std::string low = plan_of(*home.files.problem, home.domain);
  CHECK(low.find("(recharge robot1 corridor2)") != std::string::npos);
  CHECK(low.find("(soothed_received senior1") != std::string::npos);
  // Full, the same robot goes straight for the water.
  pddl::Problem full = *home.files.problem;
  for (pddl::NumericFact& f : full.numeric_init) {
    if (f.function.name == "battery") f.value = 100.0;
  }
  CHECK(plan_of(full, home.domain).find("recharge") == std::string::npos);
}

TEST_CASE("a home run with batteries recharges, never goes below a reserve, logs it and replays",
          "[home][battery]") {
  const HomeSettings settings = low_battery_run();
  EventLog log;
  const HomeSummary summary = run_home(settings, log);
  const std::vector<LogEvent>& events = log.events();
  CHECK(summary.comforted >= 1);
  const bool recharged = std::any_of(events.begin(), events.end(), [](const LogEvent& e) {
    return e.type == "action_start" && e.payload["action"].get<std::string>().rfind("(recharge ", 0) == 0;
  });
  CHECK(recharged);
  // The simulated world's lowest level over the run, robot by robot.
  REQUIRE(summary.batteries.size() == 2);
  for (const auto& [robot, b] : summary.batteries) {
    INFO(robot);
    CHECK(b.reserve == 20.0);
    CHECK(b.lowest >= b.reserve - kNumericSlack);
    CHECK_FALSE(b.below_reserve);
  }
  CHECK(summary.batteries.at("robot1").lowest < 30.0);  // senior1's robot drained
  // Every mission ends with its robots able to reach the dock (24 here),
  // so robot1 recharged beyond what serving alone would need.
  for (const auto& [robot, b] : summary.batteries) CHECK(b.level >= 24.0 - kNumericSlack);
  CHECK(summary.json().contains("batteries"));
  CHECK(count(events, "battery") == 2);
  for (const LogEvent& e : events) {
    if (e.type == "action_end" && !e.robot.empty()) CHECK(e.payload.contains("battery"));
  }
  CHECK(settings.json().contains("battery"));
  CHECK_FALSE(default_home_settings(kAssistedLiving).json().contains("battery"));

  std::stringstream text;
  for (const LogEvent& e : events) text << to_json(e).dump() << "\n";
  const LogReading reading = read_event_log(text, "run.jsonl");
  const HomeSettings read_back = HomeSettings::from_json(reading.events.front()["settings"]);
  CHECK(read_back.battery);
  CHECK(read_back.battery_options.initial == 30.0);
  EventLog again;
  run_home(read_back, again);
  CHECK_FALSE(first_difference(reading, again.events()).has_value());
}

}  // namespace alplan::home
