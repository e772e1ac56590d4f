#include "benchmarks/harness/suite.h"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "tests/support/test_paths.h"

using namespace alplan::bench;

TEST_CASE("a suite folder lists every domain+problem pair of the IPC set") {
  const std::vector<SuiteProblem> suite = load_suite(alplan::test::benchmarks_dir() + "/ipc");
  std::map<std::string, int> indexed;
  for (const auto& [domain, counts] : alplan::test::benchmark_index()) indexed[domain] = counts.problems;
  REQUIRE(indexed.size() >= 37);
  int indexed_total = 0;
  for (const auto& [domain, n] : indexed) indexed_total += n;
  CHECK(suite.size() == static_cast<std::size_t>(indexed_total));
  std::map<std::string, int> per_domain;
  for (const SuiteProblem& p : suite) ++per_domain[p.domain];
  CHECK(per_domain == indexed);
  CHECK(per_domain["ipc-2004/airport-temporal-time-windows-adl"] == 50);
  // openstacks 2008 has a domain file per problem.
  for (const SuiteProblem& p : suite) {
    if (p.domain == "ipc-2008/openstacks-temporal-satisficing-strips" && p.number == 7) {
      CHECK(p.domain_file.find("domains/domain-7.pddl") != std::string::npos);
    }
  }
  const std::size_t domains = indexed.size();
  CHECK(first_problems(suite, 5).size() == domains * 5);
  // Instances 6-10, the test set: five of every domain, none of the first five.
  const std::vector<SuiteProblem> test_set = problems_in_range(suite, 6, 10);
  CHECK(test_set.size() == domains * 5);
  for (const SuiteProblem& p : test_set) CHECK(p.number >= 6);
  CHECK(problems_in_range(suite, 1, 5).size() == domains * 5);
  const std::vector<SuiteProblem> largest = largest_problems(suite);
  CHECK(largest.size() == domains);
}

TEST_CASE("a suite list names pairs relative to its folder") {
  const std::string dir = std::filesystem::temp_directory_path() / "alplan_suite_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/list.txt") << "# a comment\nd/domain.pddl p/instance-3.pddl\n\n";
  const std::vector<SuiteProblem> suite = load_suite(dir + "/list.txt");
  REQUIRE(suite.size() == 1);
  CHECK(suite[0].domain_file == dir + "/d/domain.pddl");
  CHECK(suite[0].number == 3);
  CHECK_THROWS(load_suite(dir + "/missing"));
}
