// The grounding pipeline as passes with plain data between them:
// AST --normalize--> NormalizedTask --reachability--> ReachableSet
//     --instantiate--> GroundTask (+ axiom strata).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "pddl_parser/ast.h"
#include "planner/ground_task.h"
#include "planner/normalize.h"

namespace alplan {

// Raised when a task uses something grounding cannot represent (for example
// derived predicates that are not stratifiable); the message names it.
class GroundingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct GroundingOptions {
  NormalizeOptions names;
};

std::shared_ptr<const GroundTask> ground(const pddl::Domain& domain, const pddl::Problem& problem,
                                         const GroundingOptions& options = {});
std::shared_ptr<const GroundTask> ground(std::shared_ptr<const NormalizedTask> task);

// Strata of the derived predicates (index: PredicateId; 0 for basic ones):
// a predicate's stratum is above those it depends on negatively and not
// below those it depends on positively. Throws GroundingError if impossible.
std::vector<std::uint32_t> derived_strata(const NormalizedTask& task);

}  // namespace alplan
