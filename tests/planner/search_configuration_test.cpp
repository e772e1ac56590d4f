// The search configuration language (planner/search_configuration.h):
// expressions parse into components and print back to what parses the same;
// aliases name the configurations the planner used to build from flags;
// malformed expressions are refused with their place.
#include "planner/search_configuration.h"

#include <catch2/catch.hpp>

#include "planner/grounder.h"
#include "planner/planner.h"
#include "tests/support/task_loader.h"

using namespace alplan;
using K = EngineSpec::Kind;

namespace {

std::string error_of(const std::string& expression) {
  try {
    parse_search_configuration(expression);
  } catch (const SearchConfigurationError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("every alias parses and prints back to an expression that parses the same") {
  for (const std::string& name : alias_names()) {
    INFO(name);
    const SearchConfiguration c = alias(name);
    CHECK(parse_search_configuration(c.to_string()).engine == c.engine);
  }
}

TEST_CASE("the default configuration is EHC, then its fallback portfolio with a complete search taking turns") {
  const EngineSpec e = alias("default").engine;
  REQUIRE(e.kind == K::Then);
  REQUIRE(e.children.size() == 2);
  const EngineSpec& ehc = e.children[0];
  CHECK(ehc.kind == K::Ehc);
  CHECK(ehc.expansions == 20000);
  CHECK(ehc.time_share == Approx(0.25));
  CHECK(ehc.goal_orders);
  const EngineSpec& fallback = e.children[1];
  REQUIRE(fallback.kind == K::Portfolio);
  REQUIRE(fallback.children.size() == 5);
  CHECK(fallback.children[0].goal_orders);
  CHECK_FALSE(fallback.children[0].typed);
  CHECK(fallback.children[1].typed);
  CHECK(fallback.children[1].novelty == 2);
  CHECK(fallback.children[2].deferred);
  CHECK(fallback.children[3].kind == K::Wastar);
  CHECK(fallback.children[3].weight == 3.0);
  // Ties in h by makespan in the plain greedy search and weighted A* only.
  CHECK(fallback.children[0].makespan_ties);
  CHECK(fallback.children[3].makespan_ties);
  CHECK_FALSE(fallback.children[1].makespan_ties);
  CHECK_FALSE(fallback.children[2].makespan_ties);
  CHECK_FALSE(fallback.children[4].makespan_ties);
  CHECK_FALSE(fallback.children[3].complete);
  // The complete search is a member, not a phase after the portfolio: the
  // others may never exhaust (differential tester, task 4294967418).
  CHECK(fallback.children[4].complete);
  CHECK(fallback.children[4].kind == K::Wastar);
  CHECK_FALSE(fallback.children[4].goal_orders);
  // An equal turn for its first expansions, then a small share.
  CHECK(fallback.children[4].share == Approx(0.02));
  CHECK(fallback.children[4].share_after == 1000);
  for (std::size_t k = 0; k < 4; ++k) CHECK_FALSE(fallback.children[k].complete);
}

TEST_CASE("the anytime alias runs weighted A* with falling weights after the default") {
  const EngineSpec e = alias("anytime").engine;
  REQUIRE(e.kind == K::Anytime);
  CHECK(e.weights == std::vector<double>{5, 3, 2, 1.5, 1});
  CHECK(e.children.front() == alias("default").engine);
  const EngineSpec capped = with_anytime(alias("default"), 3.0, 500).engine;
  CHECK(capped.weights == std::vector<double>{5, 3});
  CHECK(capped.expansions == 500);
  // The weights may search with a heuristic of their own (adapt's landmark
  // cuts after the default's first plan).
  const EngineSpec own = parse_search_configuration("anytime(ehc(trpg), weights=[5, 3], heuristic=lmcut)").engine;
  CHECK(own.own_heuristic);
  CHECK(own.heuristic.kind == HeuristicSpec::Kind::LmCut);
  CHECK(own.children.front().heuristic.kind == HeuristicSpec::Kind::Trpg);
  CHECK(parse_search_configuration(SearchConfiguration{own}.to_string()).engine == own);
  CHECK_FALSE(e.own_heuristic);
}

TEST_CASE("the quality alias is the anytime configuration, by name and inside an expression") {
  CHECK(alias("quality").engine == alias("anytime").engine);
  CHECK(parse_search_configuration("quality").engine == alias("anytime").engine);
  CHECK(configuration_named("quality").engine == configuration_named("anytime").engine);
}

TEST_CASE("components take their options by name") {
  const EngineSpec e =
      parse_search_configuration(
          "then(ehc(trpg(helpful=false), expansions=100), portfolio(gbfs(blind, queue=typed, novelty=1, deferred=true),"
          " wastar(trpg, w=2, order=metric), turns=evaluations), complete(wastar(trpg(repetitions=false, balance=false),"
          " w=1)))")
          .engine;
  REQUIRE(e.children.size() == 3);
  CHECK_FALSE(e.children[0].heuristic.helpful);
  CHECK(e.children[0].expansions == 100);
  const EngineSpec& greedy = e.children[1].children[0];
  CHECK(greedy.heuristic.kind == HeuristicSpec::Kind::Blind);
  CHECK(greedy.typed);
  CHECK(greedy.novelty == 1);
  CHECK(greedy.deferred);
  CHECK(e.children[1].children[1].metric_order);
  CHECK(e.children[1].share_evaluations);
  CHECK(parse_search_configuration(SearchConfiguration{e}.to_string()).engine == e);
  CHECK(e.children[1].children[1].weight == 2.0);
  CHECK_FALSE(e.children[2].heuristic.repetitions);
  CHECK_FALSE(e.children[2].heuristic.balance);
  // EHC tries helpful children shortest makespan first unless told otherwise.
  CHECK(e.children[0].makespan_first);
  const EngineSpec listed = parse_search_configuration("ehc(trpg, children=listed)").engine;
  CHECK_FALSE(listed.makespan_first);
  CHECK(SearchConfiguration{listed}.to_string() == "ehc(trpg, children=listed)");
  CHECK(parse_search_configuration("ehc(trpg, children=makespan)").engine.makespan_first);
}

TEST_CASE("ties by makespan and the neighbourhood improvement are options that print back") {
  const EngineSpec greedy = parse_search_configuration("gbfs(trpg, ties=makespan)").engine;
  CHECK(greedy.makespan_ties);
  CHECK(SearchConfiguration{greedy}.to_string() == "gbfs(trpg, ties=makespan)");
  CHECK_FALSE(parse_search_configuration("wastar(trpg, ties=fifo)").engine.makespan_ties);
  const EngineSpec improving =
      parse_search_configuration("anytime(gbfs, weights=[2], ties=makespan, improve=neighbourhood(by=actions))").engine;
  CHECK(improving.makespan_ties);
  CHECK(improving.neighbourhood_depth == 1);
  CHECK(improving.neighbourhood_actions);
  CHECK(SearchConfiguration{improving}.to_string() ==
        "anytime(gbfs(trpg), weights=[2], ties=makespan, improve=neighbourhood(by=actions, depth=1, max_depth=4))");
  CHECK(parse_search_configuration(SearchConfiguration{improving}.to_string()).engine == improving);
  const EngineSpec states =
      parse_search_configuration("anytime(gbfs, improve=neighbourhood(depth=2, max_depth=8))").engine;
  CHECK_FALSE(states.neighbourhood_actions);
  CHECK(states.neighbourhood_depth == 2);
  CHECK(states.neighbourhood_max_depth == 8);
  CHECK(parse_search_configuration("anytime(gbfs)").engine.neighbourhood_depth == 0);
  // Without max_depth the rounds may go at least as deep as the first.
  CHECK(parse_search_configuration("anytime(gbfs, improve=neighbourhood(depth=8))").engine.neighbourhood_max_depth == 8);
  // New weights keep the anytime's own options.
  const SearchConfiguration rewritten = with_anytime(SearchConfiguration{improving}, 2.0);
  CHECK(rewritten.engine.makespan_ties);
  CHECK(rewritten.engine.neighbourhood_actions);
  CHECK(rewritten.engine.neighbourhood_depth == 1);
  CHECK(rewritten.engine.weights == std::vector<double>{5, 3, 2});
}

TEST_CASE("a malformed configuration is refused with its place and what was expected") {
  CHECK(error_of("gbfs(trpg, ties=random)").find("ties is fifo or makespan") != std::string::npos);
  CHECK(error_of("ehc(trpg, ties=makespan)").find("ehc has no option 'ties'") != std::string::npos);
  CHECK(error_of("anytime(gbfs, improve=gbfs)").find("improve is neighbourhood") != std::string::npos);
  CHECK(error_of("anytime(gbfs, improve=neighbourhood(by=plans))").find("by is states or actions") != std::string::npos);
  CHECK(error_of("anytime(gbfs, improve=neighbourhood(depth=4, max_depth=2))").find("max_depth is below depth") !=
        std::string::npos);
  CHECK(error_of("anytime(gbfs, improve=neighbourhood(depth=9))").find("a whole number from 1 to 8") != std::string::npos);
  CHECK(error_of("anytime(gbfs, improve=neighbourhood(depth=1e30))").find("a whole number from 1 to 8") !=
        std::string::npos);
  CHECK(error_of("anytime(gbfs, improve=neighbourhood(depth=1.5))").find("a whole number from 1 to 8") !=
        std::string::npos);
  CHECK(error_of("anytime(gbfs, improve=neighbourhood(width=2))").find("neighbourhood has no option 'width'") !=
        std::string::npos);
  CHECK(error_of("gbfs(trpg, queue=typed").find("character 23") != std::string::npos);
  CHECK(error_of("gbfs(trpg, queue=typed").find("expected ')'") != std::string::npos);
  CHECK(error_of("dfs").find("unknown engine 'dfs'") != std::string::npos);
  CHECK(error_of("gbfs(ff)").find("unknown heuristic 'ff'") != std::string::npos);
  CHECK(error_of("wastar(trpg, w=0)").find("w must be positive") != std::string::npos);
  CHECK(error_of("complete(ehc)").find("complete takes a gbfs or a wastar") != std::string::npos);
  CHECK(error_of("complete(gbfs(trpg, goal_orders=true))").find("cannot prune by goal orders") != std::string::npos);
  CHECK(error_of("portfolio(then(ehc))").find("a portfolio takes") != std::string::npos);
  CHECK(error_of("gbfs(trpg, w=2)").find("gbfs has no option 'w'") != std::string::npos);
  CHECK(error_of("ehc(trpg, time_share=2)").find("at most 1") != std::string::npos);
  CHECK(error_of("anytime(gbfs, weights=[0.5])").find("at least 1") != std::string::npos);
  CHECK(error_of("gbfs(trpg) x").find("after the configuration") != std::string::npos);
  CHECK(error_of("portfolio(gbfs, turns=seconds)").find("turns is expansions or evaluations") != std::string::npos);
  CHECK(error_of("portfolio(gbfs, wastar(trpg, share=0))").find("share is a share") != std::string::npos);
  CHECK(error_of("portfolio(gbfs, wastar(trpg, share=1.5))").find("share is a share") != std::string::npos);
  CHECK(error_of("ehc(trpg, children=random)").find("children is makespan or listed") != std::string::npos);
  CHECK(error_of("gbfs(trpg, children=listed)").find("gbfs has no option 'children'") != std::string::npos);
  CHECK(error_of("ehc(trpg, share=0.5)").find("ehc has no option 'share'") != std::string::npos);
  CHECK_THROWS_AS(alias("lama"), SearchConfigurationError);
}

TEST_CASE("the old flags shape the named searches as they did") {
  SearchShorthands s;
  s.search = "gbfs";
  s.novelty = true;
  s.knobs.type_exploration = false;
  const EngineSpec g = configuration_from(s).engine;
  CHECK(g.kind == K::Gbfs);
  CHECK_FALSE(g.typed);
  CHECK(g.novelty == 2);
  s.search = "wastar";
  s.knobs.weight = 2;
  s.metric_order = true;
  s.anytime = true;
  const EngineSpec w = configuration_from(s).engine;
  REQUIRE(w.kind == K::Anytime);
  CHECK(w.metric_order);
  CHECK(w.children.front().kind == K::Wastar);
  CHECK(w.children.front().weight == 2.0);
  SearchShorthands d;
  d.knobs.ehc_time_share = 0.0;
  d.knobs.fallback_deferred = false;
  d.knobs.goal_orders = false;
  const EngineSpec e = configuration_from(d).engine;
  CHECK(e.children[0].time_share == 0.0);
  CHECK_FALSE(e.children[0].goal_orders);
  REQUIRE(e.children[1].children.size() == 4);  // the deferred GBFS dropped; the complete search stays
  CHECK(e.children[1].children.back().complete);
  CHECK(configuration_named("ehc").engine == alias("default").engine);
  CHECK(configuration_named("then(ehc, complete(wastar))").engine.children.size() == 2);
}

// Two actions that exclude each other; only one leads to the goal.
const char* const kLockDomain = R"(
(define (domain lock) (:requirements :strips :negative-preconditions) (:predicates (a) (b) (goal))
  (:action one :parameters () :precondition (not (b)) :effect (a))
  (:action two :parameters () :precondition (not (a)) :effect (b))
  (:action three :parameters () :precondition (a) :effect (goal))))";
const char* const kLockProblem = "(define (problem l) (:domain lock) (:init) (:goal (goal)))";

TEST_CASE("a blind complete search plans, and proves what the relaxation cannot") {
  const test::LoadedTask loaded = test::load_task_text(kLockDomain, kLockProblem);
  PlannerOptions options;
  options.search = parse_search_configuration("complete(wastar(blind, w=1))");
  const PlannerResult solved = Planner(ground(loaded.normalized), options).plan();
  REQUIRE(solved.status == PlannerResult::Status::Solved);
  CHECK(solved.best()->plan.steps.size() == 2);
  CHECK(solved.best()->engine.find("complete") != std::string::npos);
}

TEST_CASE("portfolio members with a share take their turns, and a portfolio of them only does not stall") {
  const test::LoadedTask loaded = test::load_task_text(kLockDomain, kLockProblem);
  PlannerOptions options;
  options.node_limit = 10000;
  for (const char* text : {"portfolio(gbfs(blind, share=0.1), complete(wastar(blind, w=1, share=0.1)))",
                           "portfolio(complete(wastar(blind, w=1, share=0.01, share_after=0)), gbfs(blind), "
                           "turns=evaluations)",
                           "portfolio(complete(wastar(blind, w=1, share=0.5)))"}) {
    INFO(text);
    options.search = parse_search_configuration(text);
    const PlannerResult solved = Planner(ground(loaded.normalized), options).plan();
    CHECK(solved.status == PlannerResult::Status::Solved);
  }
  // The unsolvable variant: the shared complete member still proves it when
  // the member with an equal turn has exhausted its space.
  const test::LoadedTask locked = test::load_task_text(R"(
(define (domain lock) (:requirements :strips :negative-preconditions) (:predicates (a) (b) (goal))
  (:action one :parameters () :precondition (not (b)) :effect (a))
  (:action three :parameters () :precondition (and (a) (b)) :effect (goal))))",
                                                        "(define (problem l) (:domain lock) (:init) (:goal (goal)))");
  options.search = parse_search_configuration("portfolio(gbfs(blind), complete(wastar(blind, w=1, share=0.01)))");
  const PlannerResult proved = Planner(ground(locked.normalized), options).plan();
  INFO(proved.message);
  CHECK(proved.status == PlannerResult::Status::Unsolvable);
}
