// Constructs used without their :requirements flag: one warning per flag,
// at the first use, none when the flag (or one implying it) is declared;
// PDDL+ sections refused by name.
#include <catch2/catch.hpp>

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"

using namespace alplan::pddl;

namespace {

std::vector<Diagnostic> warnings_of(const std::string& requirements, const std::string& body) {
  const std::string text = "(define (domain d)\n  (:requirements " + requirements +
                           ")\n  (:predicates (p ?x) (q ?x))\n" + body + ")\n";
  const DomainParseResult r = parse_domain(text, "d.pddl");
  REQUIRE(r.ok());
  std::vector<Diagnostic> warnings;
  for (const Diagnostic& d : check_domain(*r.ast, "d.pddl")) {
    if (d.severity == Severity::Warning) warnings.push_back(d);
  }
  return warnings;
}

const char* kNegative =
    "  (:action a :parameters (?x) :precondition (and (p ?x) (not (q ?x))) :effect (q ?x))\n"
    "  (:action b :parameters (?x) :precondition (not (p ?x)) :effect (p ?x))\n";

const char* kMixed =
    "  (:functions (f ?x))\n"
    "  (:durative-action m :parameters (?x) :duration (= ?duration 1)\n"
    "    :condition (at start (p ?x)) :effect (at end (increase (f ?x) 1)))\n"
    "  (:action a :parameters (?x) :precondition (or (p ?x) (q ?x)) :effect (when (p ?x) (q ?x)))\n";

}  // namespace

TEST_CASE("requirements: a negative precondition without its flag is warned about once, at its first use") {
  const std::vector<Diagnostic> w = warnings_of(":strips", kNegative);
  REQUIRE(w.size() == 1);
  CHECK(w[0].line == 4);
  CHECK(w[0].column == 57);
  CHECK(w[0].message ==
        "a negative condition (not (q ...)) is used without the requirement :negative-preconditions (or :adl) in "
        ":requirements; read as if declared");
}

TEST_CASE("requirements: the flag, or one implying it, silences the warning") {
  CHECK(warnings_of(":strips :negative-preconditions", kNegative).empty());
  CHECK(warnings_of(":adl", kNegative).empty());
}

TEST_CASE("requirements: durative actions, numbers, disjunctions and conditional effects") {
  const std::vector<Diagnostic> w = warnings_of(":strips", kMixed);
  REQUIRE(w.size() == 4);
  CHECK(w[0].message.rfind("the numeric function (f) is used without the requirement :numeric-fluents", 0) == 0);
  CHECK(w[3].message.rfind("the durative action m is used without the requirement :durative-actions", 0) == 0);
  CHECK(w[1].message.rfind("a disjunction (or ...) is used without the requirement :disjunctive-preconditions", 0) == 0);
  CHECK(w[2].message.rfind("a conditional effect (when ...) is used without the requirement :conditional-effects", 0) ==
        0);
  // :fluents and :durative-actions (through :timed-initial-literals) cover two.
  CHECK(warnings_of(":fluents :timed-initial-literals :adl", kMixed).empty());
}

TEST_CASE("requirements: (total-cost) alone asks for :action-costs") {
  const std::vector<Diagnostic> w = warnings_of(":strips", "  (:functions (total-cost))\n");
  REQUIRE(w.size() == 1);
  CHECK(w[0].message.rfind("the function (total-cost) is used without the requirement :action-costs", 0) == 0);
  CHECK(warnings_of(":action-costs", "  (:functions (total-cost))\n").empty());
}

TEST_CASE("PDDL+ processes and events are refused by name, at their place") {
  const DomainParseResult r = parse_domain(
      "(define (domain d)\n  (:functions (level))\n"
      "  (:process fill :parameters () :precondition (< (level) 10) :effect (increase (level) (* #t 1)))\n"
      "  (:event full :parameters () :precondition (>= (level) 10) :effect (assign (level) 10)))\n",
      "d.pddl");
  REQUIRE(r.diagnostics.size() == 2);
  CHECK(r.diagnostics[0].to_string().rfind("d.pddl:3:4: error: PDDL+ processes (:process) are not supported", 0) == 0);
  CHECK(r.diagnostics[1].to_string().rfind("d.pddl:4:4: error: PDDL+ events (:event) are not supported", 0) == 0);
}
