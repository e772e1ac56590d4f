// A brute-force planner for tiny temporal tasks, the oracle of the
// differential tester. It shares no code with the planner: it grounds the
// actions itself (every action on every tuple of objects of its parameters'
// types, through the reference semantics' World) and asks the reference
// semantics (oracle/judge.h, exact comparisons) about every timed plan it
// enumerates.
//
// The bound, within which it is complete (it tries every plan in it, and
// prunes only prefixes no extension can mend; see brute_force.cpp):
//  - at most `max_steps` steps;
//  - each step starts within `offsets` epsilons of an anchor, or ends within
//    `offsets` epsilons of one, where the anchors are 0, every timed
//    literal's time and every start and end of the steps that start no
//    later than it;
//  - a durative step lasts a duration its constraints name (the bounds of a
//    range, its fixed value), or one that ends it within `offsets` epsilons
//    of an anchor; where the constraint reads the state, a duration from
//    the lattice 0, q, 2q, .. `max_duration` (q = `quantum`).
// Plans whose times are chains of durations, literal times and epsilon
// gaps lie inside; a plan whose step must start at a time no such chain
// gives (halfway through a gap, say) does not. What it finds is a plan (the
// reference semantics said so); what it does not find says nothing beyond
// the bound, and a search cut short by `max_judgements` says nothing at all.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "oracle/timed_plan.h"
#include "pddl_parser/ast.h"

namespace alplan::differential {

struct BruteForceOptions {
  int max_steps = 3;
  int offsets = 1;
  double epsilon = 0.001;
  double quantum = 0.5;
  double max_duration = 5.0;
  std::uint64_t max_judgements = 300000;
  // Judge with the symmetric mutex rule as well (oracle/ownership.h).
  bool symmetric_mutex = false;
  // Judge with the epsilon-separated rule as well (oracle/judge.h): no
  // interfering happenings closer than `epsilon`.
  bool epsilon_separated = false;
};

struct BruteForceResult {
  std::optional<oracle::TimedPlan> plan;
  std::uint64_t judgements = 0;
  bool cut_short = false;  // max_judgements reached before the bound was covered
  std::string error;       // the task could not be judged at all
};

BruteForceResult brute_force_plan(std::shared_ptr<const pddl::Domain> domain,
                                  std::shared_ptr<const pddl::Problem> problem, const BruteForceOptions& options = {});

// The bound in words, for reports.
std::string describe_bound(const BruteForceOptions& options);

}  // namespace alplan::differential
