// PDDL 3 planned (issue 30): hard constraints compiled (pddl3_compilation.h)
// hold in every plan; preferences are costs the anytime rounds lower
// (preference_search.h); what the compilation cannot express is refused by
// name.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "planner/grounder.h"
#include "planner/pddl3_compilation.h"
#include "planner/planner.h"
#include "planner/search_configuration.h"
#include "planner/validator.h"
#include "tests/support/pddl3_planning.h"
#include "tests/support/task_loader.h"

using namespace alplan;

namespace {

// A lamp that can be switched on and off, a door to open: each test adds
// its constraints to this task.
const char* const kLamp = R"(
(define (domain lamp) (:requirements :strips :durative-actions :constraints :preferences)
  (:predicates (lit) (open) (warm))
  (:durative-action switch-on :parameters () :duration (= ?duration 2)
    :condition (at start (not (lit))) :effect (at end (lit)))
  (:durative-action switch-off :parameters () :duration (= ?duration 1)
    :condition (at start (lit)) :effect (at end (not (lit))))
  (:durative-action heat :parameters () :duration (= ?duration 4)
    :condition (over all (lit)) :effect (at end (warm)))
  (:durative-action open-door :parameters () :duration (= ?duration 3)
    :effect (at end (open))))
)";

std::string problem(const std::string& goal, const std::string& constraints, const std::string& metric = "") {
  return "(define (problem p) (:domain lamp) (:init) (:goal " + goal + ") (:constraints " + constraints + ")" +
         (metric.empty() ? "" : " (:metric " + metric + ")") + ")";
}

PlannerResult plan(const std::string& problem_text, PlannerOptions options = {}) {
  return test::plan_texts(kLamp, problem_text, options);
}

// The printed plan is valid on the original task, constraints included.
ValidationResult check_valid(const std::string& problem_text, const PlannerResult& result) {
  return test::check_printed_plan_valid(kLamp, problem_text, result);
}

bool has_step(const PlannerResult& result, const std::string& action) {
  return result.best()->text.find("(" + action + ")") != std::string::npos;
}

}  // namespace

TEST_CASE("a hard sometime makes the plan pass through a state it would not need") {
  const std::string p = problem("(open)", "(sometime (lit))");
  const PlannerResult result = plan(p);
  check_valid(p, result);
  CHECK(has_step(result, "switch-on"));
}

TEST_CASE("a hard at end joins the goal") {
  const std::string p = problem("(open)", "(at end (warm))");
  const PlannerResult result = plan(p);
  check_valid(p, result);
  CHECK(has_step(result, "heat"));
}

TEST_CASE("a hard within is a deadline the schedule meets, and one it cannot meet gives no plan") {
  const std::string met = problem("(open)", "(within 2.5 (lit))");
  check_valid(met, plan(met));
  // switch-on takes 2: (lit) cannot hold by 1.5.
  const PlannerResult missed = plan(problem("(open)", "(within 1.5 (lit))"));
  INFO(missed.message);
  CHECK(missed.plans.empty());
  CHECK(missed.status != PlannerResult::Status::InternalError);
}

TEST_CASE("a hard always is kept in every state the search makes") {
  // Heating needs the lamp lit; the lamp may never be lit while the door is open.
  const std::string p = problem("(and (warm) (open))", "(always (or (not (lit)) (not (open))))");
  const PlannerResult result = plan(p);
  check_valid(p, result);
  CHECK(has_step(result, "switch-off"));
}

TEST_CASE("an always false where the plan starts is proven unsolvable") {
  const test::LoadedTask loaded = test::load_task_text(
      kLamp, "(define (problem p) (:domain lamp) (:init (lit) (open)) (:goal (warm)) "
             "(:constraints (always (or (not (lit)) (not (open))))))");
  const PlannerResult result = Planner(ground(loaded.normalized), {}).plan();
  CHECK(result.status == PlannerResult::Status::Unsolvable);
  CHECK(result.message.find("always") != std::string::npos);
}

TEST_CASE("a hard constraint the compilation cannot express is refused by name and place") {
  const PlannerResult result = plan(problem("(open)", "(at-most-once (and (lit) (open)))"));
  CHECK(result.status == PlannerResult::Status::Unsupported);
  CHECK(result.message.find("at-most-once") != std::string::npos);
  CHECK(result.message.find("not a fact or a disjunction of facts") != std::string::npos);
  CHECK(result.message.find(":1:") != std::string::npos);
}

TEST_CASE("a hard always-within is met by a watch of at most its span around the trigger") {
  // Once lit, the door must be open within 4: open-door (3) must be under way
  // when the lamp comes on.
  const std::string p = problem("(and (warm) (open))", "(always-within 4 (lit) (open))");
  const PlannerResult result = plan(p);
  check_valid(p, result);
  // Heating takes 4 with the lamp lit: warm cannot follow lit within 1. No
  // plan, and no proof either, since the watches may miss plans.
  PlannerOptions bounded;
  bounded.node_limit = 5000;
  const PlannerResult missed = plan(problem("(warm)", "(always-within 1 (lit) (warm))"), bounded);
  INFO(missed.message);
  CHECK(missed.plans.empty());
  CHECK(missed.status != PlannerResult::Status::Unsolvable);
  CHECK(missed.status != PlannerResult::Status::InternalError);
}

TEST_CASE("a hard always-within whose requirement a timed literal breaks is refused by name") {
  const test::LoadedTask loaded = test::load_task_text(
      kLamp, "(define (problem p) (:domain lamp) (:init (at 9 (not (open)))) (:goal (warm)) "
             "(:constraints (always-within 4 (lit) (open))))");
  const PlannerResult result = Planner(ground(loaded.normalized), {}).plan();
  CHECK(result.status == PlannerResult::Status::Unsupported);
  CHECK(result.message.find("a timed literal breaks its requirement") != std::string::npos);
}

TEST_CASE("the first plan ignores preferences, anytime rounds enforce those that pay") {
  // Being warm saves 10; being lit at the end saves 1 but costs a plan that
  // leaves the lamp on, which the cheap preference against it (weight 5) forbids.
  const std::string p = problem("(and (open) (preference w (warm)))",
                                "(and (preference dark (at end (not (lit)))) (preference on (sometime (lit))))",
                                "minimize (+ (* 10 (is-violated w)) (* 5 (is-violated dark)) (is-violated on))");
  const PlannerResult first = plan(p);
  const ValidationResult v1 = check_valid(p, first);
  CHECK(v1.value == Approx(11.0));  // the door alone: warm and on violated
  PlannerOptions options;
  options.search = with_anytime(alias("pddl3"));
  options.time_limit = 10.0;
  const PlannerResult improved = plan(p, options);
  const ValidationResult v2 = check_valid(p, improved);
  CHECK(v2.value == Approx(0.0));  // on, heat, off: every preference met
  for (std::size_t i = 1; i < improved.plans.size(); ++i) {
    CHECK(improved.plans[i].validation.value < improved.plans[i - 1].validation.value);
  }
}

TEST_CASE("a maximised metric counts the better plan as the larger value") {
  const std::string p = problem("(open)", "(preference w (sometime (warm)))",
                                "maximize (* 3 (- 1 (is-violated w)))");
  PlannerOptions options;
  options.search = with_anytime(alias("pddl3"));
  options.time_limit = 10.0;
  const PlannerResult result = plan(p, options);
  const ValidationResult v = check_valid(p, result);
  CHECK(v.value == Approx(3.0));
}

TEST_CASE("a precondition preference counts per action, and enforced it joins the condition") {
  const char* const domain = R"(
(define (domain move) (:requirements :strips :typing :durative-actions :preferences)
  (:types place) (:predicates (at ?p - place) (road ?a ?b - place) (safe ?a ?b - place))
  (:durative-action go :parameters (?a ?b - place) :duration (= ?duration 1)
    :condition (and (at start (at ?a)) (at start (road ?a ?b)) (at start (preference careful (safe ?a ?b))))
    :effect (and (at start (not (at ?a))) (at end (at ?b)))))
)";
  const char* const problem_text = R"(
(define (problem m) (:domain move) (:objects a b c - place)
  (:init (at a) (road a c) (road a b) (road b c) (safe a b) (safe b c))
  (:goal (at c)) (:metric minimize (+ (total-time) (* 5 (is-violated careful)))))
)";
  const test::LoadedTask loaded = test::load_task_text(domain, problem_text);
  PlannerOptions options;
  options.search = with_anytime(alias("pddl3"));
  options.time_limit = 10.0;
  const PlannerResult result = Planner(ground(loaded.normalized), options).plan();
  INFO(result.message);
  REQUIRE(result.status == PlannerResult::Status::Solved);
  const ValidationResult& v = result.best()->validation;
  CHECK(v.preference_violations.at("careful") == 0.0);
  CHECK(v.value == Approx(2.001).margin(0.01));  // by b, safely: 2 units and a separation
}

TEST_CASE("compilation: witnesses per disjunct, deadlines as timed literals, no preferences left") {
  const test::LoadedTask loaded =
      test::load_task_text(kLamp, problem("(open)", "(and (within 7 (or (lit) (warm))) (preference q (sometime (open))))"));
  const auto task = ground(loaded.normalized);
  REQUIRE(needs_compilation(*task));
  PreferenceSelection none;
  none.enforced.assign(task->lifted->pddl3.preferences.size(), false);
  const CompiledTrajectory c = compile_trajectory(*task, none);
  REQUIRE(!c.refused);
  CHECK_FALSE(needs_compilation(*c.task));
  CHECK(c.task->actions.size() == task->actions.size() + 2);  // one witness per disjunct
  REQUIRE(c.task->timed_literals.size() == 1);
  // Two epsilons (0.001 by default) after 7: the witness reads by 7.001
  // what the happenings up to 7 made.
  CHECK(c.task->timed_literals[0].time == Approx(7.002));
  CHECK(compile_trajectory(*task, none, {}, 0.01).task->timed_literals[0].time == Approx(7.02));
  CHECK_FALSE(c.task->timed_literals[0].positive);
  PreferenceSelection q = none;
  q.enforced.assign(none.enforced.size(), true);
  CHECK(compile_trajectory(*task, q).task->actions.size() == task->actions.size() + 3);
}

TEST_CASE("compilation: a disjunction left in the goal becomes a derived goal fact the heuristic reads") {
  // (at end (or (warm) (open))) joins the goal as a formula; the compiled goal
  // asks a derived fact instead, one axiom per disjunct, and nothing else.
  const std::string p = problem("(lit)", "(at end (or (warm) (open)))");
  const test::LoadedTask loaded = test::load_task_text(kLamp, p);
  const auto task = ground(loaded.normalized);
  PreferenceSelection none;
  none.enforced.assign(task->lifted->pddl3.preferences.size(), false);
  const CompiledTrajectory c = compile_trajectory(*task, none);
  REQUIRE(c.task);
  CHECK(c.task->goal.complex.empty());
  REQUIRE(c.task->axioms.size() == task->axioms.size() + 2);
  const FactId head = c.task->axioms.back().head;
  CHECK(c.task->is_derived(head));
  CHECK(std::find(c.task->goal.positive.begin(), c.task->goal.positive.end(), head) != c.task->goal.positive.end());
  const PlannerResult result = plan(p);
  check_valid(p, result);
  CHECK((has_step(result, "heat") || has_step(result, "open-door")));
}

TEST_CASE("the preferences engine reads, prints and goes outermost only") {
  CHECK(parse_search_configuration("preferences(gbfs, rounds=false)").to_string() ==
        "preferences(gbfs(trpg), rounds=false)");
  CHECK_THROWS_AS(parse_search_configuration("then(preferences(gbfs))"), SearchConfigurationError);
  CHECK_THROWS_AS(parse_search_configuration("anytime(preferences(gbfs))"), SearchConfigurationError);
  const SearchConfiguration anytime = with_anytime(alias("pddl3"));
  CHECK(anytime.engine.kind == EngineSpec::Kind::Preferences);
  CHECK(anytime.engine.children.front().kind == EngineSpec::Kind::Anytime);
  const PreferencePlan p = preference_plan(anytime);
  CHECK(p.rounds);
  CHECK(p.improve);
  CHECK_FALSE(preference_plan(alias("pddl3")).rounds);
  // As users name it: `--alias pddl3` and `--search pddl3 --anytime`.
  SearchShorthands named;
  named.search = "pddl3";
  named.anytime = true;
  const SearchConfiguration from_flags = configuration_from(named);
  CHECK(from_flags.engine.kind == EngineSpec::Kind::Preferences);
  CHECK(from_flags.engine.children.front().kind == EngineSpec::Kind::Anytime);
}

namespace {

// The lamp task planned from a state observed at `now`, after `history`
// (each a time and the facts true then, by name).
PlannerResult plan_observed(const std::string& problem_text, double now, const std::vector<std::string>& facts,
                            const std::vector<std::pair<double, std::vector<std::string>>>& history,
                            PlannerOptions options = {}) {
  const test::LoadedTask loaded = test::load_task_text(kLamp, problem_text);
  const std::shared_ptr<const GroundTask> task = ground(loaded.normalized);
  auto ids = [&](const std::vector<std::string>& names) {
    std::vector<FactId> out;
    for (const std::string& name : names) {
      for (FactId f = 0; f < task->facts.size(); ++f) {
        if (task->fact_name(f) == name) out.push_back(f);
      }
    }
    REQUIRE(out.size() == names.size());
    std::sort(out.begin(), out.end());
    return out;
  };
  PlanningStart start = initial_start(*task);
  start.now = now;
  start.facts = ids(facts);
  for (const auto& [time, seen] : history) start.history.push_back(ObservedState{time, ids(seen), task->initial_values});
  if (!std::isfinite(options.time_limit)) options.time_limit = 20.0;
  return Planner(task, options).plan_from(start);
}

}  // namespace

TEST_CASE("from an observed state, a within met before needs nothing more and one missed before is proven lost") {
  const std::string p = problem("(open)", "(within 10 (warm))");
  // Warm at 6, cold again by 20: the deadline is past, but it was met.
  const PlannerResult met = plan_observed(p, 20.0, {}, {{0.0, {}}, {6.0, {"(warm)"}}, {15.0, {}}});
  INFO(met.message);
  REQUIRE(met.status == PlannerResult::Status::Solved);
  CHECK(met.best()->validation.valid);
  CHECK_FALSE(has_step(met, "heat"));
  CHECK(met.best()->plan.steps.front().time.value_or(0.0) >= 20.0);
  // Never warm before 20: no plan from here can meet it, and that is a proof.
  const PlannerResult missed = plan_observed(p, 20.0, {}, {{0.0, {}}, {15.0, {}}});
  CHECK(missed.status == PlannerResult::Status::Unsolvable);
  CHECK(missed.message.find("(within 10") != std::string::npos);
  // Before the deadline, its absolute time still binds the new plan.
  const PlannerResult open = plan_observed(p, 1.0, {}, {{0.0, {}}});
  REQUIRE(open.status == PlannerResult::Status::Solved);
  CHECK(open.best()->validation.valid);
  CHECK(has_step(open, "heat"));
}

TEST_CASE("from an observed state, an always broken before is proven lost and a preference met before costs nothing") {
  const std::string hard = problem("(open)", "(always (not (warm)))");
  const PlannerResult broken = plan_observed(hard, 8.0, {}, {{0.0, {}}, {5.0, {"(warm)"}}});
  CHECK(broken.status == PlannerResult::Status::Unsolvable);
  const std::string soft = problem("(open)", "(preference p (sometime (warm)))", "minimize (is-violated p)");
  PlannerOptions anytime;
  anytime.search = with_anytime(alias("pddl3"));
  anytime.time_limit = 2.0;
  const PlannerResult seen = plan_observed(soft, 8.0, {}, {{0.0, {}}, {5.0, {"(warm)"}}}, anytime);
  REQUIRE(seen.status == PlannerResult::Status::Solved);
  CHECK(seen.best()->validation.value == Approx(0.0));
  CHECK_FALSE(has_step(seen, "heat"));
  // Not seen before: the rounds make the plan warm the room.
  const PlannerResult unseen = plan_observed(soft, 8.0, {}, {{0.0, {}}}, anytime);
  REQUIRE(unseen.status == PlannerResult::Status::Solved);
  CHECK(unseen.best()->validation.value == Approx(0.0));
  CHECK(has_step(unseen, "heat"));
}
