// adapt minimises the metric plus a penalty per change to the old plan's
// remaining steps, changes counted as Fox et al. (ICAPS 2006) count them:
// actions added plus actions removed, over multisets of ground actions
// (repair/adapt_strategy.cpp). Removing an old step is a change: the cases
// below fail where only added actions were penalised.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "pddl_parser/parser.h"
#include "planner/grounder.h"
#include "planner/normalize.h"
#include "planner/validator.h"
#include "repair/reformulation.h"
#include "repair/repair_strategy.h"
#include "repair/stable_compilation.h"

using namespace alplan;
using namespace alplan::repair;

namespace {

// Trucks carry a package over roads (stable_repair_test.cpp's domain);
// COSTS is where a drive's cost goes, FUNCTIONS where total-cost is declared.
std::string haul_domain(const std::string& functions, const std::string& costs, const std::string& extra = "") {
  return R"(
(define (domain haul)
  (:requirements :typing :durative-actions)
  (:types truck place pkg)
  (:predicates (at ?t - truck ?p - place) (pat ?k - pkg ?p - place) (in ?k - pkg ?t - truck)
               (road ?a ?b - place) )" + extra + R"()
  )" + functions + R"(
  (:durative-action drive :parameters (?t - truck ?a ?b - place) :duration (= ?duration 10)
    :condition (and (at start (at ?t ?a)) (over all (road ?a ?b)))
    :effect (and (at start (not (at ?t ?a))) (at end (at ?t ?b)) )" + costs + R"())
  (:durative-action load :parameters (?k - pkg ?t - truck ?p - place) :duration (= ?duration 2)
    :condition (and (at start (pat ?k ?p)) (over all (at ?t ?p)))
    :effect (and (at start (not (pat ?k ?p))) (at end (in ?k ?t))))
  (:durative-action unload :parameters (?k - pkg ?t - truck ?p - place) :duration (= ?duration 2)
    :condition (and (at start (in ?k ?t)) (over all (at ?t ?p)))
    :effect (and (at start (not (in ?k ?t))) (at end (pat ?k ?p)))))
)";
}

// Two trucks at a; roads a-b, b-c, a-d, d-c (both ways); k goes from a to c.
std::string haul_problem(const std::string& numeric = "", const std::string& metric = "(total-time)") {
  return R"(
(define (problem move-k) (:domain haul)
  (:objects t1 t2 - truck a b c d - place k - pkg)
  (:init (at t1 a) (at t2 a) (pat k a) )" + numeric + R"(
         (road a b) (road b a) (road b c) (road c b) (road a d) (road d a) (road d c) (road c d))
  (:goal (pat k c))
  (:metric minimize )" + metric + R"())
)";
}

// t1 carries k over b.
const char* kDelivery = R"(
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

  Fixture(const std::string& old_plan, const std::string& domain_text = haul_domain("", ""),
          const std::string& problem_text = haul_problem()) {
    const auto d = pddl::parse_domain(domain_text, "haul.pddl");
    REQUIRE(d.ok());
    const auto p = pddl::parse_problem(problem_text, "move-k.pddl");
    REQUIRE(p.ok());
    domain = d.ast;
    problem = p.ast;
    const PlanReadResult plan = read_plan(old_plan, "old.plan");
    REQUIRE(plan.ok());
    old = bind_plan(ground(*domain, *problem), plan.plan, 0.001);
    for (const pddl::Atom& a : problem->init) observed.atoms.insert(key_of(a));
    for (const pddl::NumericFact& v : problem->numeric_init) observed.values[key_of(v.function)] = v.value;
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

  std::vector<std::string> old_names() const { return step_names_from(old, 0.0); }

  // Whether the plan solves the problem reformulated from the observed
  // state (at time 0 nothing runs), as VAL would say.
  bool valid(const ExecutingPlan& plan) const {
    const pddl::Problem from = reformulate(*domain, *problem, observed, {}, 0.0);
    PlanValidator validator(std::make_shared<const NormalizedTask>(normalize(*domain, from)));
    return validator.validate(read_plan(plan_text(plan), "new.plan").plan).valid;
  }
};

std::size_t occurrences(const ExecutingPlan& plan, const std::string& step) {
  const std::vector<std::string> names = step_names_from(plan, 0.0);
  return static_cast<std::size_t>(std::count(names.begin(), names.end(), step));
}

bool says(const RepairResult& r, const std::string& text) { return r.how.find(text) != std::string::npos; }

StrategyOptions generous() {
  StrategyOptions options;
  options.adapt_budget = 2.0;  // the default's 0.25 s is for the studies' homes; a loaded machine needs more
  return options;
}

}  // namespace

TEST_CASE("adapt, of two repairs adding as many steps, takes the one that removes fewer") {
  // The old plan also drives t2 to d, which the goal does not need. k is
  // found at b: both repairs load there (one step added, the load at a
  // removed); dropping t2's drive too removes one more. Penalising only
  // additions made that free, and the planner dropped it (distance 3).
  Fixture f(std::string(kDelivery) + "0.000: (drive t2 a d) [10.000]\n");
  f.observed.set({"pat", "k", "a"}, false);
  f.observed.set({"pat", "k", "b"}, true);
  const RepairResult r = make_strategy("adapt", generous())->repair(f.request());
  INFO(r.how);
  REQUIRE(r.repaired);
  CHECK(r.fallback.empty());
  CHECK(occurrences(*r.plan, "(drive t2 a d)") == 1);
  CHECK(occurrences(*r.plan, "(load k t1 b)") == 1);
  CHECK(plan_distance(f.old_names(), step_names_from(*r.plan, 0.0)) == 2);
  CHECK(r.how.find("adapted the old plan: 4 of its 5 remaining steps are kept, 1 removed, 1 added (distance 2, "
                   "each change weighed 100 against the metric)") == 0);
  CHECK(f.valid(*r.plan));
}

TEST_CASE("adapt counts the removals of a repeated action once per occurrence") {
  // t2 goes a-b, b-a, a-b, which the goal does not need. Each occurrence
  // is a step of the old plan: with nothing failed adapt keeps all three
  // (removing them was free when only additions were penalised).
  Fixture f(std::string(kDelivery) +
            "0.000: (drive t2 a b) [10.000]\n10.001: (drive t2 b a) [10.000]\n20.002: (drive t2 a b) [10.000]\n");
  const RepairResult all = make_strategy("adapt", generous())->repair(f.request());
  INFO(all.how);
  REQUIRE(all.repaired);
  CHECK(occurrences(*all.plan, "(drive t2 a b)") == 2);
  CHECK(plan_distance(f.old_names(), step_names_from(*all.plan, 0.0)) == 0);
  // The road b-a closes. One (drive t2 a b) can still run; the other and
  // the drive back cannot: two removals, where counting actions by name
  // would see one. Keeping the second (drive t2 a b) by returning over c
  // and d would add three steps to save one removal.
  f.observed.set({"road", "b", "a"}, false);
  const RepairResult r = make_strategy("adapt", generous())->repair(f.request());
  INFO(r.how);
  REQUIRE(r.repaired);
  CHECK(r.fallback.empty());
  CHECK(occurrences(*r.plan, "(drive t2 a b)") == 1);
  CHECK(occurrences(*r.plan, "(drive t2 b a)") == 0);
  CHECK(plan_distance(f.old_names(), step_names_from(*r.plan, 0.0)) == 2);
  CHECK(says(r, "5 of its 7 remaining steps are kept, 2 removed, 0 added (distance 2,"));
  CHECK(f.valid(*r.plan));
}

TEST_CASE("adapt on a domain without total-cost keeps the old plan's truck, the makespan its metric") {
  // k is found at b, not a: the drives still serve, the load must change.
  // t2 would do as well for the makespan; only the old plan prefers t1.
  Fixture f(kDelivery, haul_domain("", ""), haul_problem("", "(total-time)"));
  f.observed.set({"pat", "k", "a"}, false);
  f.observed.set({"pat", "k", "b"}, true);
  const RepairResult r = make_strategy("adapt", generous())->repair(f.request());
  INFO(r.how);
  REQUIRE(r.repaired);
  CHECK(r.fallback.empty());
  CHECK(says(r, "3 of its 4 remaining steps are kept, 1 removed, 1 added (distance 2,"));
  CHECK(occurrences(*r.plan, "(drive t1 a b)") == 1);
  CHECK(occurrences(*r.plan, "(load k t1 b)") == 1);
  CHECK(f.valid(*r.plan));
}

TEST_CASE("adapt's compilation keeps the domain's action costs and counts the distance apart") {
  // Drives cost 3 under (+ (total-time) (total-cost)), as the home domains'
  // metric counts costs.
  Fixture f(kDelivery, haul_domain("(:functions (total-cost) - number)", "(at end (increase (total-cost) 3))"),
            haul_problem("(= (total-cost) 0)", "(+ (total-time) (total-cost))"));
  const pddl::Problem from = reformulate(*f.domain, *f.problem, f.observed, {}, 0.0);
  const StableCompilation c = compile_stability(*f.domain, from, remaining_steps(f.old, 0.0), DistanceCounter::Apart);
  CHECK(c.distance == "alplan-distance");
  REQUIRE(c.problem.metric);
  CHECK(c.problem.metric == from.metric);  // the caller weighs the distance in
  // (total-cost) counts the drives' 3 each, kept or added; alplan-distance
  // the changes, minimised here alone.
  pddl::Problem by_cost = c.problem;
  by_cost.metric->expression.kind = pddl::NumericExpression::Kind::Function;
  by_cost.metric->expression.function.name = "total-cost";
  by_cost.metric->expression.operands.clear();
  pddl::Problem by_distance = by_cost;
  by_distance.metric->expression.function.name = c.distance;
  const auto metric_of = [&](const pddl::Problem& p, const char* text) {
    PlanValidator validator(std::make_shared<const NormalizedTask>(normalize(c.domain, p)));
    const ValidationResult check = validator.validate(read_plan(text, "compiled.plan").plan);
    REQUIRE(check.valid);
    REQUIRE(check.metric);
    return *check.metric;
  };
  const char* kept = R"(
0.000: (alplan-keep-0-load) [2.000]
2.001: (alplan-keep-1-drive) [10.000]
12.002: (alplan-keep-2-drive) [10.000]
22.003: (alplan-keep-3-unload) [2.000]
)";
  CHECK(metric_of(by_cost, kept) == Approx(6.0));
  CHECK(metric_of(by_distance, kept) == Approx(0.0));
  const char* rerouted = R"(
0.000: (alplan-forgo-1)
0.000: (alplan-forgo-2)
0.000: (alplan-keep-0-load) [2.000]
2.001: (drive t1 a d) [10.000]
12.002: (drive t1 d c) [10.000]
22.003: (alplan-keep-3-unload) [2.000]
)";
  CHECK(metric_of(by_cost, rerouted) == Approx(6.0));
  CHECK(metric_of(by_distance, rerouted) == Approx(4.0));
  // stable's compilation of the same task drops the costs: its metric is
  // the distance alone.
  const StableCompilation s = compile_stability(*f.domain, from, remaining_steps(f.old, 0.0));
  CHECK(s.distance == "total-cost");
  PlanValidator stable(std::make_shared<const NormalizedTask>(normalize(s.domain, s.problem)));
  const ValidationResult check = stable.validate(read_plan(kept, "compiled.plan").plan);
  REQUIRE(check.metric);
  CHECK(*check.metric == Approx(0.0));
}

TEST_CASE("adapt repairs on a metric that counts action costs") {
  Fixture f(kDelivery, haul_domain("(:functions (total-cost) - number)", "(at end (increase (total-cost) 3))"),
            haul_problem("(= (total-cost) 0)", "(+ (total-time) (total-cost))"));
  f.observed.set({"road", "b", "c"}, false);
  f.observed.set({"road", "c", "b"}, false);
  const RepairResult r = make_strategy("adapt", generous())->repair(f.request());
  INFO(r.how);
  REQUIRE(r.repaired);
  CHECK(r.fallback.empty());
  // Keep the load and the unload, reroute over d: distance 4, as stable's
  // proven minimum (stable_repair_test.cpp); keeping the drive to b too
  // would be as close but 20 s and 6 in cost dearer.
  CHECK(says(r, "2 of its 4 remaining steps are kept, 2 removed, 2 added (distance 4, each change weighed 100 "
                "against the metric)"));
  CHECK(occurrences(*r.plan, "(drive t1 a d)") == 1);
  CHECK(occurrences(*r.plan, "(drive t1 a b)") == 0);
  CHECK(f.valid(*r.plan));
}

TEST_CASE("adapt replans, and says why, when the task cannot be compiled") {
  // The compilation's own names begin with alplan-: a domain that uses one
  // cannot be compiled, and adapt must not pretend it adapted.
  Fixture f(kDelivery, haul_domain("", "", "(alplan-mark ?t - truck)"));
  f.observed.set({"pat", "k", "a"}, false);
  f.observed.set({"pat", "k", "b"}, true);
  const RepairResult r = make_strategy("adapt", generous())->repair(f.request());
  INFO(r.how);
  REQUIRE(r.repaired);
  CHECK(r.fallback == "replan");
  CHECK(r.how.find("adapt could not plan on the stability compilation (the domain already names something "
                   "alplan-...), so it fell back to replan") == 0);
  CHECK(f.valid(*r.plan));
}

TEST_CASE("adapt keeps the whole old plan when nothing failed") {
  Fixture f(std::string(kDelivery) + "0.000: (drive t2 a d) [10.000]\n");
  const RepairResult r = make_strategy("adapt", generous())->repair(f.request());
  INFO(r.how);
  REQUIRE(r.repaired);
  CHECK(plan_distance(f.old_names(), step_names_from(*r.plan, 0.0)) == 0);
  CHECK(says(r, "5 of its 5 remaining steps are kept, 0 removed, 0 added (distance 0,"));
}
