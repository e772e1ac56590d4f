// The basic facts and numeric variables a derived fact depends on, through
// every axiom that can derive it, transitively. VAL treats a condition on a
// derived predicate as a condition on all of them when it checks the members
// of one happening for interference (DerivedGoal::markOwnedPreconditions
// marks the whole derivation formula): a happening that adds or deletes one
// of them at the time another reads the derived fact is a mutex, since the
// derived value may change in between. The validator judges mutexes so, and
// the planner's partial plan orders such happenings epsilon apart.
//
// Recursive rules (PSR's `fed` through `closed` switches) form cycles; the
// support of every fact of a cycle is the union over the cycle, so a result
// is stored only once a search from its fact has finished (a memo written
// while a cycle was still open would miss what lies behind it).
#pragma once

#include <map>
#include <vector>

#include "planner/ground_task.h"

namespace alplan {

class DerivedSupport {
 public:
  explicit DerivedSupport(const GroundTask& task);

  struct Support {
    std::vector<FactId> facts;            // basic (not derived) facts, sorted
    std::vector<NumericVarId> variables;  // sorted
  };
  // The support of a derived fact (empty for a fact no axiom derives).
  const Support& of(FactId derived);

 private:
  const GroundTask& task_;
  std::map<FactId, std::vector<std::uint32_t>> by_head_;
  std::map<FactId, Support> done_;
};

}  // namespace alplan
