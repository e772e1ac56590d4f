// A brute-force planner for tiny temporal tasks, the oracle of the
// differential tester: it shares nothing with the planner but the parser and
// the validator. It grounds the actions itself (every schema on every tuple
// of objects of the right types), and enumerates timed plans of up to
// `max_steps` steps whose start times lie on a grid (integers 0..horizon,
// and the timed literals' times, each plus 0..offsets epsilons) and whose
// durations are the constants of the duration constraint (or 0..max_duration
// when it reads anything else), asking the validator about each.
//
// Steps are enumerated in order of start time (ties by action), depth by
// depth, so the shortest plans come first. A prefix whose first violation
// lies at or before its last start is not extended: later steps start at or
// after it, and a happening cannot repair the state before it, nor undo a
// mutex or a broken invariant at its own time (VAL's semantics).
//
// What it finds is a plan (valid by construction: the validator said so);
// what it does not find says nothing beyond its grid and length.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "pddl_parser/ast.h"
#include "planner/plan.h"

namespace alplan::differential {

struct BruteForceOptions {
  int max_steps = 3;
  int horizon = 12;      // integer start times 0..horizon
  int offsets = 3;       // each plus 0..offsets epsilons
  int max_duration = 5;  // durations tried when the constraint is not constant
  double epsilon = 0.001;
  // The enumeration stops here; the result then says it was cut short.
  std::uint64_t max_validations = 400000;
};

struct BruteForceResult {
  std::optional<Plan> plan;
  std::uint64_t validations = 0;
  bool cut_short = false;  // max_validations reached before the grid was covered
  std::string error;       // the task could not be validated at all (normalisation refused it)
};

BruteForceResult brute_force_plan(const pddl::Domain& domain, const pddl::Problem& problem,
                                  const BruteForceOptions& options = {});

}  // namespace alplan::differential
