// What the corpus tests require of every PDDL file: it parses without
// errors, a domain passes the checks, and the writer's text parses back to
// the same tree.
#pragma once

#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"
#include "pddl_parser/writer.h"
#include "tests/support/diagnostics.h"

namespace alplan::test {

inline std::shared_ptr<const pddl::Domain> require_domain_round_trip(const std::string& text, const std::string& file) {
  const pddl::DomainParseResult first = pddl::parse_domain(text, file);
  REQUIRE(errors_of(first.diagnostics).empty());
  REQUIRE(first.ast);
  CHECK(errors_of(pddl::check_domain(*first.ast, file)).empty());
  const pddl::DomainParseResult second = pddl::parse_domain(pddl::write_domain(*first.ast), file + " (written)");
  REQUIRE(second.ok());
  CHECK(*second.ast == *first.ast);
  return first.ast;
}

inline std::shared_ptr<const pddl::Problem> require_problem_round_trip(const std::string& text, const std::string& file) {
  const pddl::ProblemParseResult first = pddl::parse_problem(text, file);
  REQUIRE(errors_of(first.diagnostics).empty());
  REQUIRE(first.ast);
  const pddl::ProblemParseResult second = pddl::parse_problem(pddl::write_problem(*first.ast), file + " (written)");
  REQUIRE(second.ok());
  CHECK(*second.ast == *first.ast);
  return first.ast;
}

}  // namespace alplan::test
