// The paper's Fig. 2 heads: the parser must point at the figure's two slips
// and read the corrected form.
#include <catch2/catch.hpp>

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"
#include "tests/support/test_paths.h"

using namespace alplan::pddl;

TEST_CASE("Fig. 2 as printed: both slips are reported with their positions") {
  const std::string path = alplan::test::data_dir() + "/paper_fig2/as_printed.pddl";
  const DomainParseResult r = parse_domain(alplan::test::read_text(path), "as_printed.pddl");
  REQUIRE(r.diagnostics.size() == 2);
  CHECK(r.diagnostics[0].to_string() ==
        "as_printed.pddl:24:16: error: missing '-' before the type (either ...) of ?locatable in the parameters "
        "of be: write ?locatable - (either ...)");
  CHECK(r.diagnostics[1].to_string() ==
        "as_printed.pddl:82:44: error: expected :parameters, :duration, :condition or :effect in durative action "
        "entertainment2_suggested, found 'senior'");
}

TEST_CASE("Fig. 2 corrected: parses, and the heads are consistent with the types and predicates") {
  const std::string path = alplan::test::data_dir() + "/paper_fig2/corrected.pddl";
  const DomainParseResult r = parse_domain(alplan::test::read_text(path), "corrected.pddl");
  REQUIRE(r.ok());
  const Domain& d = *r.ast;
  CHECK(d.types.size() == 26);
  CHECK(d.predicates.size() == 14);
  REQUIRE(d.durative_actions.size() == 9);
  CHECK(d.durative_actions[8].name == "entertainment2_suggested");
  CHECK(d.durative_actions[8].parameters[1].types == TypeNames{"tv", "desktop"});
  CHECK(d.predicates[0].parameters[0].types.size() == 5);
  // Fig. 2 gives heads only: the one thing the checker may miss is each
  // action's duration, which the full domain adds. Its functions are used
  // without :fluents, a warning.
  const std::vector<Diagnostic> findings = check_domain(d, "corrected.pddl");
  REQUIRE(findings.size() == 10);
  for (const Diagnostic& f : findings) {
    if (f.severity == Severity::Warning) {
      CHECK(f.message.find("without the requirement :numeric-fluents") != std::string::npos);
    } else {
      CHECK(f.message.find("has no ?duration constraint") != std::string::npos);
    }
  }
}
