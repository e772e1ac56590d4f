// An action's duration window read once when it cannot change between
// states (constant_duration_window), which the relaxation and the successor
// generator use instead of evaluating it per state; evaluated per state
// when a constraint reads a fluent.
#include <catch2/catch.hpp>
#include <cmath>

#include "planner/grounder.h"
#include "planner/planner.h"
#include "planner/successor_generator.h"
#include "tests/support/ground_names.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

// `dist` is static and, as satellite's slew times between some directions,
// undefined for b -> a; `level` changes, so `charge`'s window depends on the
// state.
const char* const kRoads = R"(
(define (domain roads) (:requirements :typing :durative-actions :fluents)
  (:types place)
  (:predicates (at ?p - place) (charged))
  (:functions (dist ?a ?b - place) (level))
  (:durative-action go :parameters (?a ?b - place) :duration (= ?duration (dist ?a ?b))
    :condition (at start (at ?a))
    :effect (and (at start (not (at ?a))) (at end (at ?b))))
  (:durative-action charge :parameters () :duration (<= ?duration (- 10 (level)))
    :condition (at start (< (level) 10))
    :effect (and (at end (assign (level) 10)) (at end (charged)))))
)";

std::shared_ptr<const GroundTask> roads() {
  const char* const problem = R"(
(define (problem p) (:domain roads) (:objects a b - place)
  (:init (at a) (= (dist a b) 4) (= (level) 3))
  (:goal (and (at b) (charged))))
)";
  return ground(test::load_task_text(kRoads, problem).normalized);
}

SearchState initial_state(const GroundTask& task) {
  SearchState state(static_cast<std::uint32_t>(task.facts.size()), task.initial_values);
  for (FactId f : task.initial_facts) state.set_fact(f, true);
  return state;
}

}  // namespace

TEST_CASE("a duration of static values is read once, the same window the state gives") {
  const auto task = roads();
  const GroundAction& go = task->actions[test::action_named(*task, "(go a b)")];
  const std::optional<DurationWindow> constant = constant_duration_window(go, Moment::Start);
  REQUIRE(constant.has_value());
  CHECK(constant->valid);
  CHECK(constant->min == 4.0);
  CHECK(constant->max == 4.0);
  const DurationWindow evaluated = duration_window(go, Moment::Start, initial_state(*task));
  CHECK(evaluated.min == constant->min);
  CHECK(evaluated.max == constant->max);
}

TEST_CASE("an undefined static duration is a constant window that admits no duration") {
  // Not `none`: that would send every evaluation back to evaluating it,
  // and so to throwing and catching an error for it (satellite's turn_to
  // spent a quarter of its time there).
  const auto task = roads();
  const GroundAction& back = task->actions[test::action_named(*task, "(go b a)")];
  const std::optional<DurationWindow> constant = constant_duration_window(back, Moment::Start);
  REQUIRE(constant.has_value());
  CHECK_FALSE(constant->valid);
  CHECK_FALSE(duration_window(back, Moment::Start, initial_state(*task)).valid);
}

TEST_CASE("a duration that reads a fluent has no constant window") {
  const auto task = roads();
  const GroundAction& charge = task->actions[test::action_named(*task, "(charge)")];
  CHECK_FALSE(constant_duration_window(charge, Moment::Start).has_value());
  const DurationWindow window = duration_window(charge, Moment::Start, initial_state(*task));
  CHECK(window.valid);
  CHECK(window.min == 0.0);
  CHECK(window.max == 7.0);
}

TEST_CASE("the planner uses the defined road and never the undefined one") {
  PlannerOptions options;
  options.time_limit = 10.0;
  const PlannerResult r = Planner(roads(), options).plan();
  REQUIRE(r.status == PlannerResult::Status::Solved);
  REQUIRE(r.best());
  const std::string& text = r.best()->text;
  CHECK(text.find("(go a b) [4.000]") != std::string::npos);
  CHECK(text.find("(go b a)") == std::string::npos);
  CHECK(text.find("(charge)") != std::string::npos);
}
