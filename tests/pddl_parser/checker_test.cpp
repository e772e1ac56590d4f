#include "pddl_parser/checker.h"

#include <catch2/catch.hpp>

#include "pddl_parser/parser.h"
#include "tests/support/test_paths.h"

using namespace alplan::pddl;

namespace {

const char* kBaseDomain =
    "(define (domain logistics)\n"                                   // 1
    "  (:requirements :typing :durative-actions :fluents)\n"         // 2
    "  (:types truck place - object city - place)\n"                 // 3
    "  (:constants hub - city)\n"                                    // 4
    "  (:predicates (at ?t - truck ?p - place) (road ?a ?b - place) (linked ?a ?b - place))\n"  // 5
    "  (:functions (distance ?a ?b - place))\n"                      // 6
    "  (:derived (linked ?a ?b - place) (road ?a ?b))\n"             // 7
    "%s"
    ")\n";

std::vector<Diagnostic> domain_errors(const std::string& body) {
  char buffer[4096];
  std::snprintf(buffer, sizeof buffer, kBaseDomain, body.c_str());
  DomainParseResult r = parse_domain(buffer, "d.pddl");
  REQUIRE(r.ok());
  std::vector<Diagnostic> all;
  for (const Diagnostic& d : check_domain(*r.ast, "d.pddl")) {
    if (d.severity == Severity::Error) all.push_back(d);
  }
  return all;
}

std::vector<Diagnostic> problem_errors(const std::string& problem) {
  DomainParseResult d = parse_domain(std::string(kBaseDomain).replace(std::string(kBaseDomain).find("%s"), 2, ""),
                                     "d.pddl");
  REQUIRE(d.ok());
  ProblemParseResult p = parse_problem(problem, "p.pddl");
  REQUIRE(p.ok());
  std::vector<Diagnostic> all;
  for (const Diagnostic& diag : check_problem(*d.ast, *p.ast, "p.pddl")) {
    if (diag.severity == Severity::Error) all.push_back(diag);
  }
  return all;
}

void require_one(const std::vector<Diagnostic>& errors, unsigned line, unsigned column, const std::string& message) {
  std::string all;
  for (const Diagnostic& d : errors) all += d.to_string() + "\n";
  INFO(all);
  REQUIRE(errors.size() == 1);
  CHECK(errors[0].line == line);
  CHECK(errors[0].column == column);
  CHECK(errors[0].message == message);
}

const std::string kProblemHead =
    "(define (problem p) (:domain logistics)\n"
    "  (:objects t1 - truck paris - city)\n";

}  // namespace

TEST_CASE("the base domain of these tests is clean") {
  CHECK(domain_errors("").empty());
}

TEST_CASE("checker: unknown requirement") {
  DomainParseResult r = parse_domain("(define (domain d) (:requirements :strips :typng))", "d.pddl");
  require_one(check_domain(*r.ast, "d.pddl"), 1, 43, "unknown requirement ':typng' (did you mean ':typing'?)");
}

TEST_CASE("checker: undefined type") {
  require_one(domain_errors("(:action a :parameters (?x - truk) :effect (and))\n"), 8, 25,
              "undefined type 'truk' of ?x (did you mean 'truck'?)");
}

TEST_CASE("checker: undefined predicate") {
  require_one(domain_errors("(:action a :parameters (?t - truck) :precondition (att ?t hub) :effect (and))\n"), 8,
              51, "undefined predicate 'att' in a condition (did you mean 'at'?)");
}

TEST_CASE("checker: undefined function") {
  require_one(domain_errors("(:durative-action a :parameters (?p - place)\n"
                            " :duration (= ?duration (distanse ?p hub)) :condition () :effect ())\n"),
              9, 25, "undefined function 'distanse' (did you mean 'distance'?)");
}

TEST_CASE("checker: undefined constant in a domain, undefined object in a problem") {
  require_one(domain_errors("(:action a :parameters (?t - truck) :effect (at ?t rome))\n"), 8, 52,
              "undefined constant 'rome' in argument 2 of (at ?t rome)");
  require_one(problem_errors(kProblemHead + "  (:init (at t1 rome))\n  (:goal (at t1 hub)))"), 3, 17,
              "undefined object 'rome' in argument 2 of (at t1 rome)");
}

TEST_CASE("checker: undefined variable") {
  require_one(domain_errors("(:action a :parameters (?t - truck) :effect (at ?t ?p))\n"), 8, 52,
              "undefined variable ?p in argument 2 of (at ?t ?p): it is not a parameter of action a nor a "
              "quantified variable");
}

TEST_CASE("checker: quantified variables are in scope only inside their quantifier") {
  CHECK(domain_errors("(:action a :parameters (?t - truck) "
                      ":precondition (exists (?p - place) (at ?t ?p)) :effect (and))\n")
            .empty());
  CHECK(domain_errors("(:action a :parameters (?t - truck) "
                      ":precondition (and (exists (?p - place) (at ?t ?p)) (at ?t ?p)) :effect (and))\n")
            .size() == 1);
}

TEST_CASE("checker: wrong arity") {
  require_one(domain_errors("(:action a :parameters (?t - truck) :effect (at ?t))\n"), 8, 45,
              "wrong arity: predicate 'at' takes 2 arguments, found 1 in (at ?t)");
  require_one(problem_errors(kProblemHead + "  (:init (= (distance paris) 3))\n  (:goal (at t1 hub)))"), 3,
              13, "wrong arity: function 'distance' takes 2 arguments, found 1 in (distance paris)");
}

TEST_CASE("checker: wrong argument type") {
  require_one(domain_errors("(:action a :parameters (?t - truck ?u - truck) :effect (at ?t ?u))\n"), 8, 63,
              "wrong argument type: argument 2 of (at ?t ?u) is ?u of type truck, but predicate 'at' expects "
              "place");
  require_one(problem_errors(kProblemHead + "  (:init (at t1 t1))\n  (:goal (at t1 hub)))"), 3, 17,
              "wrong argument type: argument 2 of (at t1 t1) is 't1' of type truck, but predicate 'at' "
              "expects place");
}

TEST_CASE("checker: a subtype may stand where its supertype is asked") {
  CHECK(problem_errors(kProblemHead + "  (:init (at t1 paris) (road paris hub))\n  (:goal (at t1 hub)))").empty());
}

TEST_CASE("checker: duplicate definitions") {
  require_one(domain_errors("(:action a :parameters () :effect (and))\n(:action a :parameters () :effect (and))\n"),
              9, 1, "action 'a' is declared twice (first at line 8)");
  require_one(domain_errors("(:action a :parameters (?x ?x) :effect (and))\n"), 8, 28,
              "parameter of action a '?x' is declared twice (first at line 8)");
  DomainParseResult r = parse_domain("(define (domain d) (:predicates (p)\n (p ?x)))", "d.pddl");
  require_one(check_domain(*r.ast, "d.pddl"), 2, 2, "predicate 'p' is declared twice (first at line 1)");
  require_one(problem_errors("(define (problem p) (:domain logistics)\n"
                             "  (:objects t1 - truck\n t1 - truck) (:init) (:goal (and)))"),
              3, 2, "object 't1' is declared twice (first at line 2)");
}

TEST_CASE("checker: timed initial literal on a non-fluent") {
  require_one(problem_errors(kProblemHead + "  (:init (at 5 (linked paris hub)))\n  (:goal (at t1 hub)))"), 3,
              10,
              "timed initial literal on the derived predicate 'linked', which is not a fluent: only its "
              ":derived rule may define it");
  require_one(problem_errors(kProblemHead + "  (:init (at 5 (= (distance paris hub) 3)))\n  (:goal (at t1 hub)))"),
              3, 10,
              "timed initial literal on the numeric function (distance paris hub): PDDL 2.2 timed initial "
              "literals set or delete a fluent atom, not a number");
}

TEST_CASE("checker: durative action without a ?duration constraint") {
  require_one(domain_errors("(:durative-action a :parameters () :duration () :condition () :effect ())\n"), 8, 1,
              "durative action a has no ?duration constraint: add :duration (= ?duration VALUE)");
  require_one(domain_errors("(:durative-action a :parameters () :condition () :effect ())\n"), 8, 1,
              "durative action a has no ?duration constraint: add :duration (= ?duration VALUE)");
}

TEST_CASE("checker: constructs out of place") {
  require_one(domain_errors("(:durative-action a :parameters (?t - truck) :duration (= ?duration 2)\n"
                            " :condition (at ?t hub) :effect ())\n"),
              9, 13,
              "the condition (at ?t hub) of durative action a needs a time: write (at start ...), (at end ...) "
              "or (over all ...)");
  require_one(domain_errors("(:action a :parameters (?t - truck) :precondition (at start (at ?t hub)) "
                            ":effect (and))\n"),
              8, 51, "(at start ...) is not allowed here: timed conditions belong in the :condition of a durative "
                     "action");
  require_one(domain_errors("(:action a :parameters (?p ?q - place) :effect (linked ?p ?q))\n"), 8, 48,
              "the effect (linked ?p ?q) changes the derived predicate 'linked', which only its :derived rule "
              "may define");
  require_one(problem_errors(kProblemHead + "  (:init)\n  (:goal (at start (at t1 hub))))"), 4, 10,
              "(at start ...) is not allowed here: timed conditions belong in the :condition of a durative "
              "action");
}

TEST_CASE("checker collects every error of a file") {
  const std::vector<Diagnostic> errors =
      domain_errors("(:action a :parameters (?t - truck) :effect (and (at ?t) (att ?t hub) (at ?t ?x)))\n");
  CHECK(errors.size() == 3);
}

TEST_CASE("checker: a problem for another domain") {
  require_one(problem_errors("(define (problem p) (:domain other) (:init) (:goal (and)))"), 1, 30,
              "the problem is for domain 'other', but the domain is 'logistics'");
}
