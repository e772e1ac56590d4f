#include "repair/random_events.h"

#include <catch2/catch.hpp>

#include <algorithm>

#include "domains/emotion_goals.h"
#include "domains/home_generator.h"
#include "domains/pddl_files.h"
#include "pddl_parser/writer.h"
#include "repair/monitor.h"
#include "repair/reformulation.h"
#include "tests/support/test_paths.h"

using namespace alplan;
using repair::ExogenousEvent;
using repair::RandomEventKind;

namespace {

const std::string kDir = test::source_dir() + "/domains/assisted_living";

// A home, the domain with the ontology's types, and a first plan for it.
struct Home {
  repair::TypeOntology ontology = repair::TypeOntology::from_file(kDir + "/types.ttl");
  pddl::Domain domain;
  pddl::Problem problem;
  repair::ExecutingPlan plan;
};

Home home(const std::string& problem_text) {
  Home h;
  const domains::LoadedFiles paper = domains::load_pddl(kDir + "/domain.pddl", kDir + "/paper-scenario-1.pddl");
  h.domain = repair::augment_domain(*paper.domain, h.ontology);
  h.problem = problem_text.empty() ? *paper.problem
                                   : *domains::load_pddl_text(pddl::write_domain(*paper.domain), "domain.pddl",
                                                              problem_text, "home.pddl")
                                          .problem;
  const repair::PlanningOutcome planned = repair::plan_in_process(h.domain, h.problem, 0.0, PlannerOptions{});
  REQUIRE(planned.plan);
  h.plan = *planned.plan;
  return h;
}

std::vector<ExogenousEvent> draw(const Home& h, std::vector<RandomEventKind> kinds, std::uint64_t seed,
                                 const repair::ExecutingPlan* plan = nullptr) {
  repair::RandomEventOptions options;
  options.kinds = std::move(kinds);
  options.seed = seed;
  repair::RandomEventGenerator generator(options);
  return generator.draw(plan ? *plan : h.plan, h.problem, &h.ontology, 1);
}

std::vector<std::string> descriptions(const std::vector<ExogenousEvent>& events) {
  std::vector<std::string> out;
  for (const ExogenousEvent& e : events) out.push_back(e.description);
  return out;
}

bool sets(const std::vector<ExogenousEvent>& events, const repair::AtomKey& atom, bool value) {
  return std::any_of(events.begin(), events.end(), [&](const ExogenousEvent& e) {
    return e.kind == ExogenousEvent::Kind::SetAtom && e.atom == atom && e.value == value;
  });
}

}  // namespace

TEST_CASE("random events are seeded: the same seed gives the same events") {
  const Home h = home("");
  const auto all = repair::all_random_event_kinds();
  CHECK(descriptions(draw(h, all, 7)) == descriptions(draw(h, all, 7)));
  bool differs = false;
  for (std::uint64_t seed = 1; seed <= 10 && !differs; ++seed) {
    differs = descriptions(draw(h, all, seed)) != descriptions(draw(h, all, seed + 100));
  }
  CHECK(differs);
}

TEST_CASE("every kind of random event is drawn against the plan it is to disturb") {
  const Home h = home("");  // the paper's scenario 1: water for a terrified senior1
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto unavailable = draw(h, {RandomEventKind::Unavailable}, seed);
    REQUIRE_FALSE(unavailable.empty());
    CHECK(unavailable.front().atom == repair::AtomKey{"available", "glass_id05"});  // the glass the plan carries
    CHECK_FALSE(unavailable.front().value);

    const auto appears = draw(h, {RandomEventKind::NewObject}, seed);
    REQUIRE(appears.size() == 1);
    CHECK(appears[0].kind == ExogenousEvent::Kind::NewObject);
    CHECK(h.ontology.augmented().count(appears[0].object.type));
    CHECK(appears[0].object.location == "kitchen1");

    const auto moves = draw(h, {RandomEventKind::SeniorMoves}, seed);
    CHECK(sets(moves, {"be", "senior1", "bedroom1"}, false));

    const auto emotion = draw(h, {RandomEventKind::EmotionChanges}, seed);
    CHECK(sets(emotion, {"terrified", "senior1"}, false));
    const bool sad = sets(emotion, {"sad", "senior1"}, true), bored = sets(emotion, {"bored", "senior1"}, true);
    CHECK(sad != bored);
    CHECK(sets(emotion, {"comfort_time", "senior1"}, true));  // the window a sad or bored senior needs opens
    for (const ExogenousEvent& e : emotion) CHECK(e.time < 300.020);  // before the glass is given

    const auto overrun = draw(h, {RandomEventKind::Overrun}, seed);
    REQUIRE(overrun.size() == 1);
    CHECK(overrun[0].kind == ExogenousEvent::Kind::Delay);
    CHECK(overrun[0].action.rfind("(move ", 0) == 0);
    CHECK(overrun[0].extra >= 10.0);
    CHECK(overrun[0].extra <= 60.0);
  }
}

TEST_CASE("a kind the plan gives no occasion for is not drawn, the others are") {
  const Home h = home("");
  repair::ExecutingPlan moves_only = h.plan;
  std::erase_if(moves_only.steps, [](const repair::ScheduledAction& s) { return s.name.rfind("(move ", 0) != 0; });
  CHECK(draw(h, {RandomEventKind::Unavailable}, 3, &moves_only).empty());
  repair::RandomEventOptions options;
  options.kinds = {RandomEventKind::Unavailable, RandomEventKind::Overrun};
  repair::RandomEventGenerator generator(options);
  const auto failure = generator.draw_failure(moves_only, h.problem, &h.ontology, 1);
  REQUIRE(failure);
  CHECK(failure->kind == RandomEventKind::Overrun);
  REQUIRE(failure->events.size() == 1);
  CHECK(failure->events[0].kind == ExogenousEvent::Kind::Delay);
}

TEST_CASE("kinds have names for the command line") {
  for (RandomEventKind k : repair::all_random_event_kinds()) CHECK(repair::random_event_kind(repair::to_string(k)) == k);
  CHECK(repair::all_random_event_kinds().size() == 9);
  CHECK(repair::study_event_kinds().size() == 7);
  CHECK_FALSE(repair::random_event_kind("earthquake"));
}

TEST_CASE("a random emotion change gets a new goal from goal generation, and the robot follows it") {
  domains::HomeOptions options;
  options.seed = 2;  // senior1 is sad; the draw below makes them bored
  const domains::GeneratedHome generated = domains::generate_home(options);
  const Home h = home(generated.problem);
  std::vector<ExogenousEvent> events = repair::timed_literal_events(h.problem);
  for (const ExogenousEvent& e : draw(h, {RandomEventKind::EmotionChanges}, 2 * 1000003u)) events.push_back(e);
  repair::WorldSimulator world(repair::initial_world(h.problem), events);
  repair::Mission mission;
  mission.domain = &h.domain;
  mission.problem = h.problem;
  mission.motivation = "senior1 is sad";
  mission.goal_generator = domains::emotion_goal_generator(std::vector<std::string>{"senior1"});
  const auto strategy = repair::make_strategy("replan", {});
  const repair::ExecutionReport report =
      repair::Monitor(repair::MonitorOptions{}).run(mission, h.plan, world, *strategy, &world, &h.ontology);
  REQUIRE(report.repairs.size() == 1);
  const repair::Explanation& e = report.repairs[0].explanation;
  CHECK(e.why.find("senior1 is sad; the plan's goal was (and (cheerful senior1))") == 0);
  CHECK(e.how.find("goal generation: senior1 is bored, so the goal is now (and (entertained senior1))") == 0);
  CHECK(report.goal_reached);
}
