// Grounding reused across problems that differ only in what holds at the
// start and in their timed literals: the problems a monitor reformulates
// from observed states during one execution (the paper's Section 6.3, step
// 3c). Relaxed reachability (reachability.h) is monotone in the initial
// facts, so a reference grounding whose fact table holds every fluent fact a
// new problem starts from or a timed literal adds, with the same domain,
// objects, static facts and values, goal and metric, already has every
// ground action the new problem can use: only the initial state and the
// timed literals are mapped onto its ids. Actions whose conditions cannot
// become true are harmless to the search and the validator.
//
// A fluent fact the reference never reaches (a senior who walked into
// another room) carries the reference's fixpoint on from that fact
// (IncrementalReachability) and grounds only what it makes reachable --
// unless an action ground before would have to change (a delete or a
// negative condition on the new fact, dropped when it was unknown). That,
// new objects, a changed static fact, goal, metric or domain are grounded
// afresh, and become the reference. Exogenous predicates (normalize.h) are
// ground as fluents, so that the world changing them (an object becoming
// unavailable) keeps the reference usable.
//
// Contract: the task returned is what ground(domain, problem, options)
// would give up to the order of ids and the presence of unreachable actions
// and facts. Not thread-safe: one cache per execution.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/grounder.h"
#include "planner/instantiate.h"
#include "planner/temporal_planner.h"
#include "planner/reachability.h"

namespace alplan {

class GroundingCache {
 public:
  struct Statistics {
    std::size_t reused = 0;    // problems mapped onto the reference
    std::size_t grounded = 0;  // problems grounded afresh
  };

  explicit GroundingCache(GroundingOptions options = {});
  ~GroundingCache();
  GroundingCache(const GroundingCache&) = delete;
  GroundingCache& operator=(const GroundingCache&) = delete;

  // Throws what ground() throws when a problem must be grounded afresh.
  std::shared_ptr<const GroundTask> ground(const pddl::Domain& domain, const pddl::Problem& problem);
  // Whether the last call reused the reference, and if not, why.
  bool last_reused() const { return last_reused_; }
  const std::string& last_miss() const { return last_miss_; }
  const Statistics& statistics() const { return statistics_; }
  // For planners on the tasks this cache gives: they share their ground
  // actions, so they can share the planner's per-task structures too.
  const std::shared_ptr<PlannerWorkspace>& planner_workspace() const { return workspace_; }

 private:
  struct Reference;
  std::shared_ptr<const GroundTask> derive(Reference& reference, const pddl::Problem& problem,
                                           std::string& miss) const;
  std::shared_ptr<const GroundTask> map_onto(const Reference& reference, const pddl::Problem& problem,
                                             std::vector<GroundKey>& unreached, std::string& miss) const;
  bool extend(Reference& reference, const std::vector<GroundKey>& atoms, std::string& miss) const;

  GroundingOptions options_;
  std::unique_ptr<Reference> reference_;
  Statistics statistics_;
  bool last_reused_ = false;
  std::string last_miss_;
  std::shared_ptr<PlannerWorkspace> workspace_ = std::make_shared<PlannerWorkspace>();
};

}  // namespace alplan
