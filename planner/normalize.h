// Pass 1 of grounding: AST -> NormalizedTask. The input must have passed the
// checker (pddl_parser/checker.h); names it cannot resolve are a bug and throw
// std::logic_error.
#pragma once

#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/normalized_task.h"

namespace alplan {

struct NormalizeOptions {
  // Names used when a message points into the files.
  std::string domain_file = "domain";
  std::string problem_file = "problem";
  // Predicates the world may change outside any action (an object becoming
  // unavailable): marked fluent although no effect changes them, so that
  // grounding keeps them as facts in conditions instead of deciding them
  // once from the initial state. A monitor's observed states can then
  // differ in them and still share one grounding (grounding_cache.h).
  std::vector<std::string> exogenous_predicates;
};

NormalizedTask normalize(const pddl::Domain& domain, const pddl::Problem& problem,
                         const NormalizeOptions& options = {});

}  // namespace alplan
