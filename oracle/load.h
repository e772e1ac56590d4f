// Reading a task for the reference semantics: the parser and its checker,
// nothing else.
#pragma once

#include <memory>
#include <string>

#include "pddl_parser/ast.h"

namespace alplan::oracle {

struct LoadedTask {
  std::shared_ptr<const pddl::Domain> domain;
  std::shared_ptr<const pddl::Problem> problem;
  std::string error;  // the parser's or checker's errors, one a line
  bool ok() const { return error.empty(); }
};

LoadedTask load_task_text(const std::string& domain_text, const std::string& problem_text,
                          const std::string& domain_name = "domain.pddl",
                          const std::string& problem_name = "problem.pddl");
LoadedTask load_task_files(const std::string& domain_path, const std::string& problem_path);

}  // namespace alplan::oracle
