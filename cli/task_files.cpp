#include "cli/task_files.h"

#include <ostream>

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"

namespace alplan::cli {
namespace {

bool report(const std::vector<pddl::Diagnostic>& diagnostics, std::ostream& out, const LoadOptions& options) {
  for (const pddl::Diagnostic& d : diagnostics) {
    if (d.severity == pddl::Severity::Error || options.show_warnings) out << d.to_string() << '\n';
  }
  return !pddl::has_errors(diagnostics);
}

}  // namespace

std::string input_name(const std::string& path) { return path == pddl::kStandardInput ? "<stdin>" : path; }

std::optional<TaskFiles> load_task_files(const std::string& domain_path, const std::string& problem_path,
                                         std::ostream& diagnostics, const LoadOptions& options) {
  if (domain_path == pddl::kStandardInput && problem_path == pddl::kStandardInput) {
    diagnostics << "-: error: standard input is given for both the domain and the problem; it can be read once\n";
    return std::nullopt;
  }
  std::vector<pddl::Diagnostic> io;
  std::string domain_text;
  std::string problem_text;
  bool ok = pddl::read_input(domain_path, domain_text, io);
  if (!problem_path.empty()) ok = pddl::read_input(problem_path, problem_text, io) && ok;
  if (!report(io, diagnostics, options) || !ok) return std::nullopt;

  TaskFiles task;
  const std::string domain_name = input_name(domain_path);
  pddl::DomainParseResult domain = pddl::parse_domain(domain_text, domain_name);
  ok = report(domain.diagnostics, diagnostics, options) && domain.ast;
  if (domain.ast && ok) ok = report(pddl::check_domain(*domain.ast, domain_name), diagnostics, options);
  task.domain = domain.ast;

  if (!problem_path.empty()) {
    const std::string problem_name = input_name(problem_path);
    pddl::ProblemParseResult problem = pddl::parse_problem(problem_text, problem_name);
    bool problem_ok = report(problem.diagnostics, diagnostics, options) && problem.ast;
    // A problem can only be checked against a domain that parsed.
    if (problem_ok && domain.ast) {
      problem_ok = report(pddl::check_problem(*domain.ast, *problem.ast, problem_name), diagnostics, options);
    }
    ok = ok && problem_ok;
    task.problem = problem.ast;
  }
  if (!ok) return std::nullopt;
  return task;
}

}  // namespace alplan::cli
