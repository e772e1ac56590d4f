// The grounding pipeline as passes with plain data between them:
// AST --normalize--> NormalizedTask --reachability--> ReachableSet
//     --instantiate--> GroundTask (+ axiom strata).
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "pddl_parser/ast.h"
#include "planner/deadline.h"
#include "planner/ground_task.h"
#include "planner/normalize.h"
#include "planner/reachability.h"

namespace alplan {

// Raised when a task uses something grounding cannot represent (for example
// derived predicates that are not stratifiable); the message names it.
class GroundingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct GroundingOptions {
  NormalizeOptions names;
  // Past this moment grounding stops with GroundingTimeout (deadline.h),
  // checked in the reachability fixpoint and the instantiation loops, so
  // that a time limit bounds the whole run, not just the search.
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

std::shared_ptr<const GroundTask> ground(const pddl::Domain& domain, const pddl::Problem& problem,
                                         const GroundingOptions& options = {});
std::shared_ptr<const GroundTask> ground(std::shared_ptr<const NormalizedTask> task,
                                         const GroundingOptions& options = {});
// The last passes alone, on a reachable set computed already (the grounding
// cache keeps its fixpoint open); the task's times.reachability stays 0.
std::shared_ptr<GroundTask> ground_reachable(std::shared_ptr<const NormalizedTask> task,
                                             const ReachableSet& reachable, const GroundingOptions& options = {});

// Strata of the derived predicates (index: PredicateId; 0 for basic ones):
// a predicate's stratum is above those it depends on negatively and not
// below those it depends on positively. Throws GroundingError if impossible.
std::vector<std::uint32_t> derived_strata(const NormalizedTask& task);

}  // namespace alplan
