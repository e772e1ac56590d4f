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

std::optional<TaskFiles> load_task_files(const std::string& domain_path, const std::string& problem_path,
                                         std::ostream& diagnostics, const LoadOptions& options) {
  std::vector<pddl::Diagnostic> io;
  std::string domain_text;
  std::string problem_text;
  bool ok = pddl::read_file(domain_path, domain_text, io);
  if (!problem_path.empty()) ok = pddl::read_file(problem_path, problem_text, io) && ok;
  if (!report(io, diagnostics, options) || !ok) return std::nullopt;

  TaskFiles task;
  pddl::DomainParseResult domain = pddl::parse_domain(domain_text, domain_path);
  ok = report(domain.diagnostics, diagnostics, options) && domain.ast;
  if (domain.ast && ok) ok = report(pddl::check_domain(*domain.ast, domain_path), diagnostics, options);
  task.domain = domain.ast;

  if (!problem_path.empty()) {
    pddl::ProblemParseResult problem = pddl::parse_problem(problem_text, problem_path);
    bool problem_ok = report(problem.diagnostics, diagnostics, options) && problem.ast;
    // A problem can only be checked against a domain that parsed.
    if (problem_ok && domain.ast) {
      problem_ok = report(pddl::check_problem(*domain.ast, *problem.ast, problem_path), diagnostics, options);
    }
    ok = ok && problem_ok;
    task.problem = problem.ast;
  }
  if (!ok) return std::nullopt;
  return task;
}

}  // namespace alplan::cli
