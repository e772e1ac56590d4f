// Parses, checks and normalises domain+problem files for tests, caching
// domains by path.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "pddl_parser/ast.h"
#include "planner/normalized_task.h"

namespace alplan::test {

struct LoadedTask {
  std::shared_ptr<const pddl::Domain> domain;
  std::shared_ptr<const pddl::Problem> problem;
  std::shared_ptr<const NormalizedTask> normalized;
};

// From files; fails the running test on any parse or check error.
LoadedTask load_task(const std::string& domain_path, const std::string& problem_path);
// From PDDL text.
LoadedTask load_task_text(const std::string& domain_text, const std::string& problem_text);

}  // namespace alplan::test
