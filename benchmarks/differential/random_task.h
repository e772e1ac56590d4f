// Small random temporal planning tasks, written as PDDL text, for testing the
// planner against a brute-force search (differential testing, as compilers
// are tested against each other: McKeeman, "Differential Testing for
// Software", Digital Technical Journal 10(1), 1998).
//
// A task has a few propositions (nullary, and unary over one or two
// objects), a few durative actions and sometimes an instantaneous one, with
// at-start / over-all / at-end conditions and start / end effects. The
// generator plants the structures temporal planners get wrong: an action
// that gives itself its own over-all condition at start, required
// concurrency (a provider's start gives what a holder needs over all, its
// end takes it back), timed initial literals opening and closing windows,
// duration inequalities, zero durations, a counter changed by numeric
// effects and compared in conditions and the goal. Durations and literal
// times are small integers, so that a grid of integer times with epsilon
// offsets holds most plans (brute_force.h).
//
// Deterministic: the same seed and options give the same text everywhere
// (the draws use the engine's raw output, not a library distribution).
#pragma once

#include <cstdint>
#include <string>

namespace alplan::differential {

struct RandomTaskOptions {
  int max_durative_actions = 3;
  int max_instant_actions = 1;
  int max_nullary = 4;       // nullary predicates
  int max_unary = 1;         // unary predicates, over the objects
  int objects = 2;
  int max_duration = 4;      // durations 0..max (0 rarely)
  int max_literal_time = 8;  // timed initial literals at 1..max
  // Chances, in percent, of each planted structure.
  int self_support = 25;
  int required_concurrency = 30;
  int timed_literals = 35;
  int numeric = 30;
  int duration_range = 20;
  int negative_conditions = 25;
};

struct RandomTask {
  std::string name;  // fuzz-<seed>
  std::string domain;
  std::string problem;
};

RandomTask random_task(std::uint64_t seed, const RandomTaskOptions& options = {});

}  // namespace alplan::differential
