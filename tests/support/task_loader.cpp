#include "tests/support/task_loader.h"

#include <catch2/catch.hpp>

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"
#include "planner/normalize.h"
#include "tests/support/test_paths.h"

namespace alplan::test {
namespace {

std::string errors(const std::vector<pddl::Diagnostic>& diagnostics) {
  std::string all;
  for (const pddl::Diagnostic& d : diagnostics) {
    if (d.severity == pddl::Severity::Error) all += d.to_string() + "\n";
  }
  return all;
}

}  // namespace

LoadedTask load_task_text(const std::string& domain_text, const std::string& problem_text) {
  LoadedTask task;
  pddl::DomainParseResult d = pddl::parse_domain(domain_text, "domain");
  INFO(errors(d.diagnostics));
  REQUIRE(d.ok());
  REQUIRE(errors(pddl::check_domain(*d.ast, "domain")).empty());
  pddl::ProblemParseResult p = pddl::parse_problem(problem_text, "problem");
  INFO(errors(p.diagnostics));
  REQUIRE(p.ok());
  INFO(errors(pddl::check_problem(*d.ast, *p.ast, "problem")));
  REQUIRE(errors(pddl::check_problem(*d.ast, *p.ast, "problem")).empty());
  task.domain = d.ast;
  task.problem = p.ast;
  task.normalized = std::make_shared<const NormalizedTask>(normalize(*d.ast, *p.ast));
  return task;
}

LoadedTask load_task(const std::string& domain_path, const std::string& problem_path) {
  return load_task_text(read_text(domain_path), read_text(problem_path));
}

}  // namespace alplan::test
