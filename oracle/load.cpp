#include "oracle/load.h"

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"

namespace alplan::oracle {
namespace {

std::string errors(const std::vector<pddl::Diagnostic>& diagnostics) {
  std::string out;
  for (const pddl::Diagnostic& d : diagnostics) {
    if (d.severity == pddl::Severity::Error) out += d.to_string() + "\n";
  }
  return out;
}

}  // namespace

LoadedTask load_task_text(const std::string& domain_text, const std::string& problem_text,
                          const std::string& domain_name, const std::string& problem_name) {
  LoadedTask task;
  const pddl::DomainParseResult d = pddl::parse_domain(domain_text, domain_name);
  const pddl::ProblemParseResult p = pddl::parse_problem(problem_text, problem_name);
  task.error = errors(d.diagnostics) + errors(p.diagnostics);
  if (!d.ok() || !p.ok()) {
    if (task.error.empty()) task.error = "the task could not be read\n";
    return task;
  }
  task.error += errors(pddl::check_domain(*d.ast, domain_name));
  task.error += errors(pddl::check_problem(*d.ast, *p.ast, problem_name));
  if (task.ok()) {
    task.domain = d.ast;
    task.problem = p.ast;
  }
  return task;
}

LoadedTask load_task_files(const std::string& domain_path, const std::string& problem_path) {
  std::string domain_text, problem_text;
  std::vector<pddl::Diagnostic> diagnostics;
  if (!pddl::read_file(domain_path, domain_text, diagnostics) || !pddl::read_file(problem_path, problem_text, diagnostics)) {
    LoadedTask task;
    task.error = errors(diagnostics);
    if (task.error.empty()) task.error = "cannot read " + domain_path + " or " + problem_path + "\n";
    return task;
  }
  return load_task_text(domain_text, problem_text, domain_path, problem_path);
}

}  // namespace alplan::oracle
