#include "pddl_parser/parser.h"

#include <catch2/catch.hpp>

#include "tests/support/test_paths.h"

using namespace alplan::pddl;

namespace {

std::string messages(const std::vector<Diagnostic>& diagnostics) {
  std::string all;
  for (const Diagnostic& d : diagnostics) all += d.to_string() + "\n";
  return all;
}

const Domain& constructs_domain() {
  static const DomainParseResult result = parse_domain(
      alplan::test::read_text(alplan::test::data_dir() + "/constructs/domain.pddl"), "domain.pddl");
  return *result.ast;
}

}  // namespace

TEST_CASE("parser reads the header, requirements, types and constants") {
  const Domain& d = constructs_domain();
  CHECK(d.name == "constructs");
  REQUIRE(d.requirements.size() == 16);
  CHECK(d.requirements.front().name == ":strips");
  REQUIRE(d.types.size() == 6);
  CHECK(d.types[3].name == "amphibian");
  CHECK(d.types[3].parents == TypeNames{"vehicle", "boat"});
  CHECK(d.types[0].parents == TypeNames{"object"});
  REQUIRE(d.constants.size() == 1);
  CHECK(d.constants[0].types == TypeNames{"place"});
}

TEST_CASE("parser reads predicates with either-typed parameters and functions with value types") {
  const Domain& d = constructs_domain();
  REQUIRE(d.predicates.size() == 5);
  CHECK(d.predicates[0].parameters[0].types == TypeNames{"vehicle", "boat"});
  CHECK(d.predicates[1].parameters[0].types == TypeNames{"place"});  // ?from ?to - place
  CHECK(d.predicates[4].parameters.empty());
  REQUIRE(d.functions.size() == 3);
  CHECK(d.functions[0].value_type == "number");
  CHECK(d.functions[1].value_type == "number");  // the default
}

TEST_CASE("parser reads instantaneous actions with ADL conditions and numeric effects") {
  const Domain& d = constructs_domain();
  REQUIRE(d.actions.size() == 1);
  const Action& a = d.actions[0];
  REQUIRE(a.precondition);
  REQUIRE(a.precondition->children.size() == 6);
  CHECK(a.precondition->children[1].kind == Condition::Kind::Not);
  const Condition& disjunction = a.precondition->children[2];
  CHECK(disjunction.kind == Condition::Kind::Or);
  CHECK(disjunction.children[0].kind == Condition::Kind::Equality);
  CHECK(disjunction.children[1].kind == Condition::Kind::Imply);
  CHECK(a.precondition->children[3].kind == Condition::Kind::Forall);
  CHECK(a.precondition->children[4].kind == Condition::Kind::Comparison);
  CHECK(a.precondition->children[4].comparison == Comparison::Less);
  CHECK(a.precondition->children[5].kind == Condition::Kind::Preference);
  CHECK(a.precondition->children[5].preference_name == "cheap");
  REQUIRE(a.effect);
  const std::vector<Effect>& e = a.effect->children;
  REQUIRE(e.size() == 6);
  CHECK(e[1].kind == Effect::Kind::Numeric);
  CHECK(e[1].assign == AssignOperator::Assign);
  CHECK(e[2].assign == AssignOperator::Increase);
  CHECK(e[3].assign == AssignOperator::ScaleUp);
  CHECK(e[4].assign == AssignOperator::ScaleDown);
  CHECK(e[5].kind == Effect::Kind::Forall);
  CHECK(e[5].children[0].kind == Effect::Kind::When);
  CHECK(e[5].children[0].children[0].kind == Effect::Kind::Delete);
}

TEST_CASE("parser reads durative actions: duration inequalities, timed conditions and effects") {
  const Domain& d = constructs_domain();
  REQUIRE(d.durative_actions.size() == 2);
  const DurativeAction& drive = d.durative_actions[0];
  CHECK(drive.name == "drive");  // written Drive
  REQUIRE(drive.duration.size() == 2);
  CHECK(drive.duration[0].comparison == Comparison::GreaterEqual);
  CHECK(drive.duration[0].value.kind == NumericExpression::Kind::Divide);
  CHECK(drive.duration[1].comparison == Comparison::LessEqual);
  const std::vector<Condition>& c = drive.condition->children;
  REQUIRE(c.size() == 4);
  CHECK(c[0].kind == Condition::Kind::Timed);
  CHECK(c[0].time == TimeSpecifier::AtStart);
  CHECK(c[0].children[0].atom.name == "at");  // (at start (at ?v ?from))
  CHECK(c[1].time == TimeSpecifier::OverAll);
  CHECK(c[2].time == TimeSpecifier::AtEnd);
  CHECK(c[3].children[0].expressions[1].kind == NumericExpression::Kind::Negate);
  const std::vector<Effect>& e = drive.effect->children;
  REQUIRE(e.size() == 5);
  CHECK(e[0].kind == Effect::Kind::Timed);
  CHECK(e[0].children[0].kind == Effect::Kind::Delete);
  CHECK(e[2].children[0].value->operands[1].kind == NumericExpression::Kind::Duration);
  CHECK(e[3].value->operands[0].kind == NumericExpression::Kind::ContinuousTime);
  CHECK(e[4].kind == Effect::Kind::Forall);
  CHECK(e[4].children[0].kind == Effect::Kind::Timed);

  const DurativeAction& wait = d.durative_actions[1];
  REQUIRE(wait.duration.size() == 1);
  CHECK(wait.duration[0].time == TimeSpecifier::AtEnd);
}

TEST_CASE("parser reads derived predicates and PDDL 3 constraints") {
  const Domain& d = constructs_domain();
  REQUIRE(d.derived_predicates.size() == 2);
  CHECK(d.derived_predicates[1].body.kind == Condition::Kind::Exists);
  REQUIRE(d.constraints);
  const std::vector<Condition>& c = d.constraints->children;
  REQUIRE(c.size() == 10);
  CHECK(c[0].kind == Condition::Kind::Always);
  CHECK(c[1].kind == Condition::Kind::Preference);
  CHECK(c[2].kind == Condition::Kind::Within);
  CHECK(c[2].numbers == std::vector<double>{10});
  CHECK(c[4].kind == Condition::Kind::AlwaysWithin);
  CHECK(c[5].numbers == std::vector<double>{1, 2});
  CHECK(c[9].kind == Condition::Kind::Timed);
}

TEST_CASE("parser reads problems: objects, numeric init, timed initial literals, goal and metric") {
  const ProblemParseResult r = parse_problem(
      alplan::test::read_text(alplan::test::data_dir() + "/constructs/problem.pddl"), "problem.pddl");
  REQUIRE(r.ok());
  const Problem& p = *r.ast;
  CHECK(p.domain_name == "constructs");
  CHECK(p.objects.size() == 6);
  CHECK(p.init.size() == 4);
  REQUIRE(p.numeric_init.size() == 5);
  CHECK(p.numeric_init[3].value == -1.25);
  CHECK(p.numeric_init[4].function.name == "total-cost");
  REQUIRE(p.timed_literals.size() == 2);
  CHECK(p.timed_literals[0].time == 10);
  CHECK(p.timed_literals[0].positive);
  CHECK(p.timed_literals[1].time == 20.5);
  CHECK_FALSE(p.timed_literals[1].positive);
  REQUIRE(p.metric);
  CHECK_FALSE(p.metric->minimize);
  CHECK(p.constraints);
}

TEST_CASE("a syntax error names the place and what was expected and found") {
  const DomainParseResult r = parse_domain("(define (domain d)\n  (:predicates (p ?x - ))\n)", "d.pddl");
  REQUIRE_FALSE(r.ok());
  REQUIRE(r.diagnostics.size() == 1);
  CHECK(r.diagnostics[0].to_string() == "d.pddl:2:24: error: expected a type name or (either ...), found ')'");
}

TEST_CASE("the parser reports every broken section, not only the first") {
  const std::string text =
      "(define (domain d)\n"
      "  (:predicates (p ?x) (q))\n"
      "  (:action a :parameters (?x) :precondition (p ?x) :effect (and (q) 3))\n"
      "  (:action b :parameters (?x) :precondition (p ?x) :effect (q))\n"
      "  (:action c :parameters ?x :effect (q))\n"
      "  (:bogus)\n"
      ")";
  const DomainParseResult r = parse_domain(text, "d.pddl");
  REQUIRE(r.ast);
  INFO(messages(r.diagnostics));
  REQUIRE(r.diagnostics.size() == 3);
  CHECK(r.diagnostics[0].line == 3);
  CHECK(r.diagnostics[0].message == "expected '(' to open an effect, found the number 3");
  CHECK(r.diagnostics[1].line == 5);
  CHECK(r.diagnostics[1].message == "expected '(' to open the parameters of c, found the variable ?x");
  CHECK(r.diagnostics[2].line == 6);
  CHECK(r.diagnostics[2].message.rfind("unknown domain section :bogus", 0) == 0);
  // The intact sections are kept.
  REQUIRE(r.ast->actions.size() == 1);
  CHECK(r.ast->actions[0].name == "b");
}

TEST_CASE("deep nesting is an error, not a stack overflow") {
  std::string text = "(define (domain d) (:predicates (p)) (:action a :parameters () :precondition ";
  for (int i = 0; i < 100000; ++i) text += "(not ";
  text += "(p)";
  for (int i = 0; i < 100000; ++i) text += ")";
  text += "))";
  const DomainParseResult r = parse_domain(text, "deep.pddl");
  REQUIRE_FALSE(r.ok());
  CHECK(r.diagnostics[0].message == "expressions nested deeper than 500 levels");
}

TEST_CASE("truncated and empty files get an error at the end") {
  DomainParseResult empty = parse_domain("", "e.pddl");
  CHECK_FALSE(empty.ok());
  CHECK(empty.diagnostics.at(0).message == "expected '(' to open (define ...), found the end of the file");
  DomainParseResult truncated = parse_domain("(define (domain d) (:predicates (p ?x", "t.pddl");
  CHECK_FALSE(truncated.ok());
  CHECK(truncated.diagnostics.at(0).message.find("found the end of the file") != std::string::npos);
}

TEST_CASE("a problem given where a domain is expected is named as such") {
  DomainParseResult r = parse_domain("(define (problem p) (:domain d))", "p.pddl");
  REQUIRE_FALSE(r.ok());
  CHECK(r.diagnostics.at(0).message == "expected a domain definition, found 'problem'");
  CHECK(detect_file_kind("; c\n(define (problem p))") == FileKind::Problem);
  CHECK(detect_file_kind("(DEFINE (Domain p))") == FileKind::Domain);
  CHECK(detect_file_kind("hello") == FileKind::Unknown);
}

TEST_CASE("(at start ...) is timed while (at x y) is the predicate at") {
  const DomainParseResult r = parse_domain(
      "(define (domain d) (:predicates (at ?a ?b))"
      "(:durative-action m :parameters (?a ?b) :duration (= ?duration 1)"
      " :condition (and (at start (at ?a ?b)) (over all (at ?a start)))"
      " :effect (at end (at ?b ?a))))",
      "d.pddl");
  REQUIRE(r.ast);
  const DurativeAction& m = r.ast->durative_actions.at(0);
  CHECK(m.condition->children[0].kind == Condition::Kind::Timed);
  CHECK(m.condition->children[1].children[0].kind == Condition::Kind::Atom);
  CHECK(m.condition->children[1].children[0].atom.args[1].name == "start");
  CHECK(m.effect->kind == Effect::Kind::Timed);
}

TEST_CASE("a problem must name its domain") {
  ProblemParseResult r = parse_problem("(define (problem p)\n (:objects a) (:init) (:goal (and)))", "p.pddl");
  REQUIRE_FALSE(r.ok());
  CHECK(r.diagnostics.back().to_string() == "p.pddl:1:1: error: the problem does not name its domain: add (:domain NAME)");
}

TEST_CASE("fuzzer finding: a problem without (:domain ...) no longer round-trips into garbage") {
  // libFuzzer found that such a problem was accepted and written as
  // (:domain ), which does not parse back. It is now an input error.
  const std::string text = alplan::test::read_text(alplan::test::data_dir() + "/fuzz/problem_without_domain.pddl");
  CHECK_FALSE(parse_problem(text, "f.pddl").ok());
}

TEST_CASE("a type marker written against its type, as in some IPC 2006 files, is read as VAL reads it") {
  const DomainParseResult r = parse_domain(
      "(define (domain d) (:requirements :typing) (:types goods place)\n"
      "  (:predicates (ready-to-load ?g -goods ?m - place) (at-1 ?p - place)))",
      "glued.pddl");
  REQUIRE(r.ok());
  const auto& ready = r.ast->predicates.front();
  REQUIRE(ready.parameters.size() == 2);
  CHECK(ready.parameters[0].types == std::vector<std::string>{"goods"});
  CHECK(ready.parameters[1].types == std::vector<std::string>{"place"});
  REQUIRE(r.diagnostics.size() == 1);
  CHECK(r.diagnostics[0].severity == Severity::Warning);
  CHECK(r.diagnostics[0].to_string().rfind("glued.pddl:2:34: warning: '-' is written against the name", 0) == 0);
  // A name with dashes inside, and negative numbers, are untouched.
  CHECK(r.ast->predicates.back().name == "at-1");
}
