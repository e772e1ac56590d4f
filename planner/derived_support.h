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

// What a derived predicate reads, by predicate and function: every basic
// predicate and function its lifted rules mention, through the derived
// predicates they mention, transitively. The planner orders snaps by this
// (task_index.cpp), not by DerivedSupport over its own axioms: the validator
// grounds axioms under a looser reachability than the planner's grounder, so
// a support taken from the planner's axioms can miss a fact the validator
// counts (PSR instance 10: (unsafe cb3 side2) has no axiom in the planner's
// task and several in the validator's, through which (affected cb3) reads
// (closed sd18); the planner put (open sd18) and (open sd17) at one time).
// Every ground support either side computes is made of instances of these
// predicates and functions, so ordering by them is safe for both.
class LiftedDerivedReads {
 public:
  explicit LiftedDerivedReads(const NormalizedTask& lifted);

  // Sorted; empty for a predicate no rule derives.
  const std::vector<PredicateId>& predicates(PredicateId derived) const { return predicates_[derived]; }
  const std::vector<FunctionId>& functions(PredicateId derived) const { return functions_[derived]; }

 private:
  std::vector<std::vector<PredicateId>> predicates_;
  std::vector<std::vector<FunctionId>> functions_;
};

}  // namespace alplan
