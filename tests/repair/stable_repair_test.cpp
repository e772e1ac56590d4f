// Repairs for plan stability on a temporal domain without action costs, as
// the IPC temporal domains are: stable finds the plan at minimum distance
// from the old one (repair/stable_compilation.h); adapt's cases are in
// adapt_strategy_test.cpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>

#include "pddl_parser/parser.h"
#include "planner/grounder.h"
#include "planner/normalize.h"
#include "planner/validator.h"
#include "repair/reformulation.h"
#include "repair/repair_strategy.h"
#include "repair/stable_compilation.h"
#include "tests/support/test_paths.h"

using namespace alplan;
using namespace alplan::repair;

namespace {

// Trucks carry a package over roads; no (total-cost).
const char* kDomain = R"(
(define (domain haul)
  (:requirements :typing :durative-actions)
  (:types truck place pkg)
  (:predicates (at ?t - truck ?p - place) (pat ?k - pkg ?p - place) (in ?k - pkg ?t - truck)
               (road ?a ?b - place))
  (:durative-action drive :parameters (?t - truck ?a ?b - place) :duration (= ?duration 10)
    :condition (and (at start (at ?t ?a)) (over all (road ?a ?b)))
    :effect (and (at start (not (at ?t ?a))) (at end (at ?t ?b))))
  (:durative-action load :parameters (?k - pkg ?t - truck ?p - place) :duration (= ?duration 2)
    :condition (and (at start (pat ?k ?p)) (over all (at ?t ?p)))
    :effect (and (at start (not (pat ?k ?p))) (at end (in ?k ?t))))
  (:durative-action unload :parameters (?k - pkg ?t - truck ?p - place) :duration (= ?duration 2)
    :condition (and (at start (in ?k ?t)) (over all (at ?t ?p)))
    :effect (and (at start (not (in ?k ?t))) (at end (pat ?k ?p)))))
)";

// Two trucks at a; roads a-b, b-c, a-d, d-c (both ways); the package goes
// from a to c.
const char* kProblem = R"(
(define (problem move-k) (:domain haul)
  (:objects t1 t2 - truck a b c d - place k - pkg)
  (:init (at t1 a) (at t2 a) (pat k a)
         (road a b) (road b a) (road b c) (road c b) (road a d) (road d a) (road d c) (road c d))
  (:goal (pat k c))
  (:metric minimize (total-time)))
)";

// The plan that failed: t1 carries k over b.
const char* kOldPlan = R"(
0.000: (load k t1 a) [2.000]
2.001: (drive t1 a b) [10.000]
12.002: (drive t1 b c) [10.000]
22.003: (unload k t1 c) [2.000]
)";

struct Fixture {
  std::shared_ptr<const pddl::Domain> domain;
  std::shared_ptr<const pddl::Problem> problem;
  ExecutingPlan old;
  WorldState observed;

  Fixture() {
    const auto d = pddl::parse_domain(kDomain, "haul.pddl");
    const auto p = pddl::parse_problem(kProblem, "move-k.pddl");
    REQUIRE(d.ok());
    REQUIRE(p.ok());
    domain = d.ast;
    problem = p.ast;
    const PlanReadResult plan = read_plan(kOldPlan, "old.plan");
    REQUIRE(plan.ok());
    old = bind_plan(ground(*domain, *problem), plan.plan, 0.001);
    for (const pddl::Atom& a : problem->init) observed.atoms.insert(key_of(a));
  }

  RepairRequest request() const {
    RepairRequest r;
    r.domain = domain.get();
    r.problem = problem.get();
    r.plan = &old;
    r.observed = observed;
    r.now = 0.0;
    return r;
  }

  std::vector<std::string> old_names() const {
    std::vector<std::string> names;
    for (const ScheduledAction& s : old.steps) names.push_back(s.name);
    return names;
  }
};

std::vector<std::string> names(const ExecutingPlan& plan) {
  std::vector<std::string> out;
  for (const ScheduledAction& s : plan.steps) out.push_back(s.name);
  return out;
}

// Whether the plan solves the problem reformulated from the observed state
// (at time 0 nothing runs, so that is an ordinary problem), as VAL would say.
bool valid_from_observed(const Fixture& f, const ExecutingPlan& plan) {
  const pddl::Problem from = reformulate(*f.domain, *f.problem, f.observed, {}, 0.0);
  PlanValidator validator(std::make_shared<const NormalizedTask>(normalize(*f.domain, from)));
  return validator.validate(read_plan(plan_text(plan), "new.plan").plan).valid;
}

bool uses(const ExecutingPlan& plan, const std::string& step) {
  const std::vector<std::string> n = names(plan);
  return std::find(n.begin(), n.end(), step) != n.end();
}

}  // namespace

TEST_CASE("stable repairs a closed road at the minimum distance and proves it") {
  // The road b-c is closed: the drive over b must go. Hand-computed
  // minimum: keep load and unload, forgo both drives, add a-d and d-c
  // (or keep a-b and add b-a, a-d, d-c): D = 4.
  Fixture f;
  f.observed.set({"road", "b", "c"}, false);
  f.observed.set({"road", "c", "b"}, false);
  const RepairResult stable = make_strategy("stable", {})->repair(f.request());
  REQUIRE(stable.repaired);
  CHECK(stable.fallback.empty());
  CHECK(stable.how.find("stable repair at distance 4 from the old plan (proven minimal") == 0);
  CHECK(stable.proven_minimal);
  CHECK(plan_distance(f.old_names(), names(*stable.plan)) == 4);
  CHECK(uses(*stable.plan, "(load k t1 a)"));
  CHECK(uses(*stable.plan, "(unload k t1 c)"));
  CHECK(valid_from_observed(f, *stable.plan));

  const RepairResult replan = make_strategy("replan", {})->repair(f.request());
  REQUIRE(replan.repaired);
  CHECK(plan_distance(f.old_names(), names(*replan.plan)) >= 4);
}

TEST_CASE("stable proves the same minimum with A* on landmark cuts as with uniform-cost search") {
  Fixture f;
  f.observed.set({"road", "b", "c"}, false);
  f.observed.set({"road", "c", "b"}, false);
  const StrategyOptions options;  // A* on lmcut, the default
  StrategyOptions uniform;
  uniform.stable_proof_search = "complete(wastar(blind, w=1, order=metric, preferred=false))";
  const RepairResult astar = make_strategy("stable", options)->repair(f.request());
  REQUIRE(astar.repaired);
  CHECK(astar.how.find("stable repair at distance 4 from the old plan (proven minimal by A* on an admissible "
                       "heuristic") == 0);
  CHECK(plan_distance(f.old_names(), names(*astar.plan)) == 4);
  CHECK(valid_from_observed(f, *astar.plan));
  // The package found at b: keep the drives, load there (D = 2, as adapt's).
  Fixture g;
  g.observed.set({"pat", "k", "a"}, false);
  g.observed.set({"pat", "k", "b"}, true);
  const RepairResult blind = make_strategy("stable", uniform)->repair(g.request());
  CHECK(blind.how.find("(proven minimal by uniform-cost search") != std::string::npos);
  const RepairResult landmarks = make_strategy("stable", options)->repair(g.request());
  REQUIRE(blind.repaired);
  REQUIRE(landmarks.repaired);
  CHECK(plan_distance(g.old_names(), names(*landmarks.plan)) == plan_distance(g.old_names(), names(*blind.plan)));
  CHECK(landmarks.how.find("(proven minimal") != std::string::npos);
  // A search whose heuristic can overestimate proves nothing, whatever it finds.
  StrategyOptions guessing;
  guessing.stable_proof_search = "complete(wastar(trpg, w=1, order=metric, preferred=false))";
  const RepairResult guessed = make_strategy("stable", guessing)->repair(g.request());
  REQUIRE(guessed.repaired);
  CHECK(guessed.how.find("not proven minimal: complete(wastar(trpg") != std::string::npos);
  CHECK_FALSE(guessed.proven_minimal);
  CHECK(landmarks.proven_minimal);
}

TEST_CASE("stable keeps the whole old plan when nothing failed") {
  Fixture f;
  const RepairResult stable = make_strategy("stable", {})->repair(f.request());
  REQUIRE(stable.repaired);
  CHECK(stable.how.find("stable repair at distance 0 from the old plan (proven minimal") == 0);
  CHECK(names(*stable.plan) == f.old_names());
}

TEST_CASE("a compiled plan costs the distance of the plan it maps to") {
  Fixture f;
  f.observed.set({"road", "b", "c"}, false);
  f.observed.set({"road", "c", "b"}, false);
  const pddl::Problem from = reformulate(*f.domain, *f.problem, f.observed, {}, 0.0);
  const StableCompilation c = compile_stability(*f.domain, from, remaining_steps(f.old, 0.0));
  REQUIRE(c.old.size() == 4);
  CHECK(ground_name(c.old[1]) == "(drive t1 a b)");
  // By hand: keep the load and the unload, forgo both drives, drive over d.
  const char* text = R"(
0.000: (alplan-forgo-1)
0.000: (alplan-forgo-2)
0.000: (alplan-keep-0-load) [2.000]
2.001: (drive t1 a d) [10.000]
12.002: (drive t1 d c) [10.000]
22.003: (alplan-keep-3-unload) [2.000]
)";
  const Plan compiled = read_plan(text, "compiled.plan").plan;
  PlanValidator validator(std::make_shared<const NormalizedTask>(normalize(c.domain, c.problem)));
  const ValidationResult check = validator.validate(compiled);
  REQUIRE(check.valid);
  REQUIRE(check.metric);
  const MappedPlan mapped = map_back(c, compiled);
  CHECK(mapped.kept == 2);
  CHECK(mapped.forgone == 2);
  CHECK(mapped.added == 2);
  std::vector<std::string> image;
  for (const PlanStep& s : mapped.plan.steps) image.push_back(ground_name({s.action, s.args}));
  CHECK(*check.metric == Approx(static_cast<double>(plan_distance(f.old_names(), image))));
  CHECK(*check.metric == Approx(4.0));
  // The mapped plan solves the uncompiled problem.
  PlanValidator original(std::make_shared<const NormalizedTask>(normalize(*f.domain, from)));
  CHECK(original.validate(mapped.plan).valid);
}

TEST_CASE("a repair during execution may keep or forgo only the steps not yet started") {
  Fixture f;
  const std::vector<OldStep> rest = remaining_steps(f.old, 2.001);
  REQUIRE(rest.size() == 3);
  CHECK(ground_name(rest.front()) == "(drive t1 a b)");
  CHECK(plan_distance({"(a)", "(b)", "(b)"}, {"(b)", "(c)"}) == 3);  // multisets: one (b) is kept
}

TEST_CASE("stable is a strategy by name") {
  const std::vector<std::string> names = strategy_names();
  CHECK(std::find(names.begin(), names.end(), "stable") != names.end());
  CHECK(make_strategy("stable", {})->name() == "stable");
}

// By hand (hidden): repairs on IPC 2002 driverlog-time when the first
// package the planner's plan loads is found at another truck location;
// prints each strategy's latency and distance. Run with
//   repair_tests "[.ipc-stability]" -s
TEST_CASE("stable, adapt and replan on driverlog-time", "[.ipc-stability]") {
  const std::string dir = test::benchmarks_dir() + "/ipc/ipc-2002/driverlog-time-automatic";
  const auto domain = pddl::parse_domain(test::read_text(dir + "/domain.pddl"), "domain.pddl");
  REQUIRE(domain.ok());
  for (int n = 1; n <= 8; ++n) {
    const std::string path = dir + "/instances/instance-" + std::to_string(n) + ".pddl";
    const auto problem = pddl::parse_problem(test::read_text(path), path);
    REQUIRE(problem.ok());
    const std::shared_ptr<const GroundTask> task = ground(*domain.ast, *problem.ast);
    PlannerOptions planner = executing_planner_options();
    planner.time_limit = 30.0;
    const PlannerResult first = Planner(task, planner).plan();
    REQUIRE(first.best());
    const ExecutingPlan old = bind_plan(task, first.best()->plan, planner.epsilon);
    WorldState observed;
    for (const pddl::Atom& a : problem.ast->init) observed.atoms.insert(key_of(a));
    for (const pddl::NumericFact& v : problem.ast->numeric_init) observed.values[key_of(v.function)] = v.value;
    // The first load's package lies at another place trucks reach.
    std::string package, from, to;
    for (const ScheduledAction& s : old.steps) {
      if (s.name.rfind("(load-truck ", 0) != 0) continue;
      const GroundAction& a = task->actions[s.action];
      package = task->lifted->objects[a.args[0]];
      from = task->lifted->objects[a.args[2]];
      break;
    }
    if (package.empty()) continue;  // nothing to load: the goal is where the packages are
    for (const pddl::Atom& a : problem.ast->init) {
      if (a.name == "link" && a.args[0].name != from) to = a.args[0].name;
    }
    observed.set({"at", package, from}, false);
    observed.set({"at", package, to}, true);
    RepairRequest request;
    request.domain = domain.ast.get();
    request.problem = problem.ast.get();
    request.plan = &old;
    request.observed = observed;
    std::vector<std::string> before;
    for (const ScheduledAction& s : old.steps) before.push_back(s.name);
    for (const char* strategy : {"replan", "adapt", "stable"}) {
      const RepairResult r = make_strategy(strategy, {})->repair(request);
      const std::size_t d = r.plan ? plan_distance(before, names(*r.plan)) : 0;
      std::printf("instance-%d (%zu steps, %s moved %s->%s) %-6s %s %.3f s distance %zu fallback '%s'\n  %s\n", n,
                  before.size(), package.c_str(), from.c_str(), to.c_str(), strategy,
                  r.repaired ? "repaired" : "FAILED", r.seconds, d, r.fallback.c_str(), r.how.c_str());
    }
  }
}
