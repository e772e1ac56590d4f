// Relaxed reachability: which ground atoms, action instantiations and axiom
// instantiations can ever occur, computed as a Datalog fixpoint in the manner
// of Fast Downward's translator (Helmert 2009, "Concise finite-domain
// representations for PDDL planning tasks", Section 5). Delete effects,
// negative and numeric conditions are ignored; disjunctive preconditions are
// split into one rule per disjunct; existential variables become rule
// variables. An instantiation exists only if every positive atom of some
// disjunct of its relaxed precondition is reachable.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "planner/fact_table.h"
#include "planner/normalized_task.h"

namespace alplan {

struct ReachabilityOptions {
  // The planner requires the at-start atoms of a durative action and those
  // of its over-all condition, the latter reachable with the help of starts
  // (a start is reachable on its at-start atoms and gives its at-start adds:
  // an invariant may come from another start in the same happening). The
  // validator, which must follow any plan it is given, requires only
  // at-start atoms.
  bool require_over_all = true;
  // Disjunctive preconditions whose DNF would exceed this many disjuncts are
  // relaxed to true instead of split.
  std::size_t max_disjuncts = 32;
  // Past this moment the fixpoint stops with GroundingTimeout (deadline.h).
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

struct Instantiation {
  std::uint32_t schema = 0;  // action schema or derived rule index
  std::vector<ObjectId> args;
};

struct ReachableSet {
  GroundKeyTable atoms;  // every reachable atom, static and fluent, in discovery order
  std::vector<Instantiation> actions;
  std::vector<Instantiation> axioms;
};

// Throws GroundingTimeout when options.deadline passes.
ReachableSet compute_reachable(const NormalizedTask& task, const ReachabilityOptions& options = {});

class Fixpoint;

// The same fixpoint kept open: atoms added later (a fact the world made true
// that no action reaches) are joined with everything known, and what they
// make reachable is appended -- earlier atoms, actions and axioms keep their
// places. Relaxed reachability is monotone, so the result equals a fixpoint
// computed from the start with those atoms in the initial state.
class IncrementalReachability {
 public:
  IncrementalReachability(std::shared_ptr<const NormalizedTask> task, const ReachabilityOptions& options = {});
  ~IncrementalReachability();
  IncrementalReachability(const IncrementalReachability&) = delete;
  IncrementalReachability& operator=(const IncrementalReachability&) = delete;

  const ReachableSet& reachable() const;
  // Throws GroundingTimeout when the deadline passes.
  void add(const std::vector<GroundKey>& atoms,
           std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt);

 private:
  std::shared_ptr<const NormalizedTask> task_;
  std::unique_ptr<Fixpoint> fixpoint_;
};

}  // namespace alplan
