// Pass 1 of grounding: AST -> NormalizedTask. The input must have passed the
// checker (pddl_parser/checker.h); names it cannot resolve are a bug and throw
// std::logic_error.
#pragma once

#include <string>

#include "pddl_parser/ast.h"
#include "planner/normalized_task.h"

namespace alplan {

struct NormalizeOptions {
  // Names used when a message points into the files.
  std::string domain_file = "domain";
  std::string problem_file = "problem";
};

NormalizedTask normalize(const pddl::Domain& domain, const pddl::Problem& problem,
                         const NormalizeOptions& options = {});

}  // namespace alplan
