#include "domains/pddl_files.h"

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"

namespace alplan::domains {
namespace {

void throw_on_errors(const std::vector<pddl::Diagnostic>& diagnostics) {
  if (!pddl::has_errors(diagnostics)) return;
  std::string message;
  for (const pddl::Diagnostic& d : diagnostics) {
    if (d.severity == pddl::Severity::Error) message += d.to_string() + "\n";
  }
  throw InputError(message);
}

std::string read(const std::string& path) {
  std::string text;
  std::vector<pddl::Diagnostic> diagnostics;
  pddl::read_file(path, text, diagnostics);
  throw_on_errors(diagnostics);
  return text;
}

}  // namespace

LoadedFiles load_pddl_text(const std::string& domain_text, const std::string& domain_name,
                           const std::string& problem_text, const std::string& problem_name) {
  pddl::DomainParseResult domain = pddl::parse_domain(domain_text, domain_name);
  throw_on_errors(domain.diagnostics);
  throw_on_errors(pddl::check_domain(*domain.ast, domain_name));
  pddl::ProblemParseResult problem = pddl::parse_problem(problem_text, problem_name);
  throw_on_errors(problem.diagnostics);
  throw_on_errors(pddl::check_problem(*domain.ast, *problem.ast, problem_name));
  return {std::move(domain.ast), std::move(problem.ast)};
}

LoadedFiles load_pddl(const std::string& domain_path, const std::string& problem_path) {
  return load_pddl_text(read(domain_path), domain_path, read(problem_path), problem_path);
}

}  // namespace alplan::domains
