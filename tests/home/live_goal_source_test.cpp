// The live goal source (home/live_goal_source.h): stress events pushed onto
// the signal service's queue from another thread become goals with windows,
// logged as the simulated home logs them; and the real-time clock.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "domains/pddl_files.h"
#include "home/event_log.h"
#include "home/given_face.h"
#include "home/home_map.h"
#include "home/live_goal_source.h"
#include "home/run_clock.h"
#include "tests/support/test_paths.h"

namespace alplan::home {
namespace {

const std::string kAssistedLiving = test::source_dir() + "/domains/assisted_living";

HomeMap default_map() {
  const domains::LoadedFiles files = domains::load_pddl(kAssistedLiving + "/domain.pddl", kAssistedLiving + "/home.pddl");
  return read_home_map(*files.problem);
}

perception::service::StressEvent stress(const std::string& senior, bool stressed) {
  perception::service::StressEvent e;
  e.senior = senior;
  e.device = "wb-" + senior;
  e.stressed = stressed;
  e.t_ms = 1700000000000ULL;
  e.stressed_fraction = stressed ? 1.0 : 0.0;
  e.votes = 3;
  return e;
}

// The operator's given emotion, as `--emotion` gives it.
FaceLooks::Look given(const std::string& emotion) {
  auto face = std::make_shared<GivenFace>("", emotion);
  return [face](const std::string&, double) {
    std::string note;
    return face->look(note);
  };
}

std::vector<std::string> types(const EventLog& log) {
  std::vector<std::string> out;
  for (const LogEvent& e : log.events()) out.push_back(e.type + ":" + e.senior);
  return out;
}

}  // namespace

TEST_CASE("stress events from the service's queue become goals with windows", "[home][live]") {
  const HomeMap map = default_map();
  const HomeSettings settings = default_home_settings(kAssistedLiving);
  EventLog log;
  perception::service::StressEventQueue queue(16);
  LiveGoalSource source(queue, given("terrified"), map, {"senior1", "senior3"}, settings, log);
  CHECK_FALSE(source.score(100.0).has_value());  // no truth to score against

  CHECK(source.sense(0.0).empty());
  CHECK(log.events().empty());

  // Pushed by another thread, as the service's request threads do.
  std::thread wristband([&] { CHECK(queue.push(stress("senior1", true))); });
  wristband.join();
  const std::vector<PerceivedGoal> goals = source.sense(5.0);
  REQUIRE(goals.size() == 1);
  const PerceivedGoal& g = goals.front();
  CHECK(g.senior == "senior1");
  CHECK(g.emotion == "terrified");
  CHECK(g.predicate == "soothed");
  CHECK(g.window == "hydration_time");
  CHECK(g.time == 5.0);
  CHECK(g.window_end == Approx(5.0 + settings.terrified_window_s));
  CHECK(types(log) == std::vector<std::string>{"stress:senior1", "emotion:senior1", "goal:senior1"});
  const LogEvent& heard = log.events().front();
  CHECK(heard.time == 5.0);
  CHECK(heard.payload.at("stressed") == true);
  CHECK(heard.payload.at("device") == "wb-senior1");
  CHECK(heard.payload.at("votes") == 3);
  CHECK(log.events().back().payload.at("goal") == "(soothed senior1)");

  // A goal in course: the senior is not looked at again.
  CHECK(source.sense(40.0).empty());
  CHECK(log.events().size() == 3);

  // The window closed first: looked at again at once, a new goal.
  source.missed(g, 605.0);
  const std::vector<PerceivedGoal> again = source.sense(606.0);
  REQUIRE(again.size() == 1);
  CHECK(again.front().window_end == Approx(606.0 + settings.terrified_window_s));

  // Comforted, then calm: no look after the grace period either.
  source.comforted(again.front(), 700.0);
  REQUIRE(queue.push(stress("senior1", false)));
  CHECK(source.sense(701.0).empty());
  CHECK(source.sense(700.0 + settings.grace_s + 1.0).empty());
  CHECK(log.events().back().type == "stress");
  CHECK(log.events().back().payload.at("stressed") == false);
}

TEST_CASE("a live sad senior's window is the longer one", "[home][live]") {
  const HomeMap map = default_map();
  const HomeSettings settings = default_home_settings(kAssistedLiving);
  EventLog log;
  perception::service::StressEventQueue queue(4);
  LiveGoalSource source(queue, given("sad"), map, {"senior3"}, settings, log);
  REQUIRE(queue.push(stress("senior3", true)));
  const std::vector<PerceivedGoal> goals = source.sense(10.0);
  REQUIRE(goals.size() == 1);
  CHECK(goals.front().predicate == "cheerful");
  CHECK(goals.front().window == "comfort_time");
  CHECK(goals.front().window_end == Approx(10.0 + settings.other_window_s));
}

TEST_CASE("a wristband of a senior the home lacks is refused", "[home][live]") {
  const HomeMap map = default_map();
  const HomeSettings settings = default_home_settings(kAssistedLiving);
  EventLog log;
  perception::service::StressEventQueue queue(4);
  CHECK_THROWS_WITH(LiveGoalSource(queue, given("sad"), map, {"senior1", "senior-01"}, settings, log),
                    Catch::Contains("a wristband belongs to senior-01, not a senior of the home"));
}

TEST_CASE("the wall clock waits until the run's time and stops at once when told", "[home][live]") {
  WallClock clock(10.0);
  const auto start = std::chrono::steady_clock::now();
  CHECK(clock.wait_until(0.2));
  CHECK(std::chrono::steady_clock::now() - start >= std::chrono::milliseconds(200));
  CHECK(clock.now() >= 0.2);
  CHECK(clock.wait_until(0.1));  // the past: no wait (time spent planning passed)
  CHECK_FALSE(clock.wait_until(10.5));  // past the run's end
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    clock.stop();
  });
  const auto waiting = std::chrono::steady_clock::now();
  CHECK_FALSE(clock.wait_until(9.0));
  stopper.join();
  CHECK(std::chrono::steady_clock::now() - waiting < std::chrono::seconds(5));
  CHECK(clock.stopped());
  CHECK_FALSE(clock.wait_until(0.0));
}

}  // namespace alplan::home
