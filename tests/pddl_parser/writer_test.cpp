#include "pddl_parser/writer.h"

#include <catch2/catch.hpp>

#include "pddl_parser/parser.h"
#include "tests/support/test_paths.h"

using namespace alplan::pddl;

TEST_CASE("numbers are written in the shortest form that reads back exactly") {
  CHECK(format_number(0) == "0");
  CHECK(format_number(-0.0) == "0");
  CHECK(format_number(12) == "12");
  CHECK(format_number(12.5) == "12.5");
  CHECK(format_number(-3.25) == "-3.25");
  CHECK(format_number(0.001) == "0.001");
  CHECK(format_number(1e20) == "100000000000000000000");
  const double third = 1.0 / 3.0;
  DomainParseResult r = parse_domain("(define (domain d) (:functions (f)) (:durative-action a :parameters () "
                                     ":duration (= ?duration " + format_number(third) + ")))",
                                     "d.pddl");
  REQUIRE(r.ast);
  CHECK(r.ast->durative_actions[0].duration[0].value.value == third);
}

TEST_CASE("writing and re-parsing the constructs files gives the same AST") {
  const std::string dir = alplan::test::data_dir() + "/constructs/";
  DomainParseResult d = parse_domain(alplan::test::read_text(dir + "domain.pddl"), "domain.pddl");
  ProblemParseResult p = parse_problem(alplan::test::read_text(dir + "problem.pddl"), "problem.pddl");
  REQUIRE(d.ok());
  REQUIRE(p.ok());
  DomainParseResult d2 = parse_domain(write_domain(*d.ast), "written");
  ProblemParseResult p2 = parse_problem(write_problem(*p.ast), "written");
  REQUIRE(d2.ok());
  REQUIRE(p2.ok());
  CHECK(*d2.ast == *d.ast);
  CHECK(*p2.ast == *p.ast);
  // The writer is a fixed point on its own output.
  CHECK(write_domain(*d2.ast) == write_domain(*d.ast));
}

TEST_CASE("AST equality sees content, not positions") {
  DomainParseResult a = parse_domain("(define (domain d) (:predicates (p ?x)))", "a");
  DomainParseResult b = parse_domain("(define (domain d)\n\n   (:predicates\n (p ?x)))", "b");
  DomainParseResult c = parse_domain("(define (domain d) (:predicates (p ?y)))", "c");
  CHECK(*a.ast == *b.ast);
  CHECK_FALSE(*a.ast == *c.ast);
}

TEST_CASE("one-line forms for messages") {
  DomainParseResult r = parse_domain(
      "(define (domain d) (:predicates (p ?x) (q)) (:functions (f ?x))"
      "(:action a :parameters (?x) :precondition (and (p ?x) (not (q)) (>= (f ?x) (+ 1 2)))"
      " :effect (and (q) (increase (f ?x) 2))))",
      "d");
  REQUIRE(r.ast);
  CHECK(write_condition(*r.ast->actions[0].precondition) == "(and (p ?x) (not (q)) (>= (f ?x) (+ 1 2)))");
  CHECK(write_effect(*r.ast->actions[0].effect) == "(and (q) (increase (f ?x) 2))");
}

TEST_CASE("fuzzer finding: untyped declarations before typed ones keep their (lack of) type") {
  // Two (:objects ...) sections, the first untyped: written as one list, the
  // second section's type would have absorbed the untyped names.
  const char* problem = "(define (problem p) (:domain d) (:objects a b) (:objects c - t) (:init) (:goal (and)))";
  ProblemParseResult first = parse_problem(problem, "p");
  REQUIRE(first.ok());
  ProblemParseResult again = parse_problem(write_problem(*first.ast), "written");
  REQUIRE(again.ok());
  CHECK(again.ast->objects[0].types.empty());
  CHECK(*again.ast == *first.ast);
  DomainParseResult domain = parse_domain("(define (domain d) (:types a) (:types b - a) (:constants x) (:constants y - a))", "d");
  REQUIRE(domain.ok());
  DomainParseResult domain_again = parse_domain(write_domain(*domain.ast), "written");
  REQUIRE(domain_again.ok());
  CHECK(*domain_again.ast == *domain.ast);
  const std::string text = alplan::test::read_text(alplan::test::data_dir() + "/fuzz/objects_in_two_sections.pddl");
  ProblemParseResult found = parse_problem(text, "f");
  REQUIRE(found.ok());
  CHECK(*parse_problem(write_problem(*found.ast), "w").ast == *found.ast);
}
