// The IPC 2006 PDDL 3 benchmarks (../shared/benchmarks/pddl3: nine domains,
// 45 problems): every file parses without error, is written back and parsed
// to the same AST (constraints, preferences and is-violated included), and
// each problem passes the semantic checks with its domain.
#include <catch2/catch.hpp>

#include <map>
#include <memory>

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"
#include "pddl_parser/writer.h"
#include "tests/support/diagnostics.h"
#include "tests/support/round_trip.h"
#include "tests/support/test_paths.h"

using namespace alplan::pddl;

using alplan::test::errors_of;

TEST_CASE("every PDDL 3 benchmark file parses, round-trips and checks") {
  const std::string root = alplan::test::benchmarks_dir() + "/pddl3/ipc-2006";
  const std::vector<std::string> files = alplan::test::files_below(root, ".pddl");
  REQUIRE(files.size() == 54);
  std::map<std::string, std::shared_ptr<const Domain>> domains;
  int problems = 0;
  for (const std::string& file : files) {
    const std::string text = alplan::test::read_text(file);
    INFO(file);
    if (detect_file_kind(text) == FileKind::Domain) {
      alplan::test::require_domain_round_trip(text, file);
      continue;
    }
    REQUIRE(detect_file_kind(text) == FileKind::Problem);
    ++problems;
    const std::shared_ptr<const Problem> problem = alplan::test::require_problem_round_trip(text, file);
    // instances/instance-N.pddl beside domain.pddl
    const std::string domain_file = file.substr(0, file.rfind("/instances/")) + "/domain.pddl";
    auto& domain = domains[domain_file];
    if (!domain) {
      const DomainParseResult d = parse_domain(alplan::test::read_text(domain_file), domain_file);
      REQUIRE(d.ok());
      domain = d.ast;
    }
    CHECK(errors_of(check_problem(*domain, *problem, file)).empty());
  }
  CHECK(problems == 45);
  CHECK(domains.size() == 9);
}
