// Small random temporal planning tasks, written as PDDL text, for testing
// the planner against a brute force that asks the reference semantics
// (differential testing, as compilers are tested against each other:
// McKeeman, "Differential Testing for Software", Digital Technical Journal
// 10(1), 1998).
//
// A task is planted, then disturbed. The plant is a chain: the goal needs
// what the last of two or three actions gives, each of which needs what the
// one before gives, so that a plan, when there is one, has two steps or
// more. Around it the generator draws the structures temporal planners get
// wrong, each with its own chance (TaskFeatures):
//  - several numeric fluents; effects whose amounts read fluents; assign,
//    scale-up, increase and decrease; comparisons between two fluents;
//  - conditional effects, decided at the effect's time or at the start;
//  - derived predicates, read by conditions and goals;
//  - negative conditions;
//  - timed initial literals at fractional times opening windows shorter
//    than, as long as and longer than the durations that use them;
//  - over-all conditions an action gives itself at its start; required
//    concurrency (a holder inside its provider, sometimes exactly as long);
//  - two actions changing one fluent at one instant inside a window too
//    short for them to be apart;
//  - zero durations and duration inequalities;
//  - PDDL 3: hard always, sometime, within and at end; goal and
//    precondition preferences in the metric.
// Durations and times are multiples of a quantum (0.5 by default), so that
// the brute force's anchored times (brute_force.h) reach every plan.
//
// Deterministic: one seed names one task everywhere (the draws use the
// engine's raw output, not a library distribution).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace alplan::differential {

struct TaskFeatures {
  // Chances, in percent, of each planted structure.
  int numeric = 40;
  int amount_from_fluent = 50;  // of numeric tasks
  int fluent_comparison = 30;   // of numeric tasks
  int assign_or_scale = 25;     // of numeric tasks
  int conditional_effects = 25;
  int derived_predicates = 20;
  int negative_conditions = 35;
  int timed_literals = 45;
  int self_support = 20;
  int required_concurrency = 30;
  int simultaneous_change = 10;
  int zero_duration = 8;
  int duration_range = 20;
  int hard_constraints = 12;
  int preferences = 12;
  int unary = 30;  // predicates over objects, actions with a parameter
};

struct GeneratorOptions {
  TaskFeatures features;
  int max_durative_actions = 3;
  int max_instant_actions = 2;
  int max_facts = 5;
  double quantum = 0.5;  // durations and timed literal times are multiples
  int max_duration_quanta = 6;
};

struct GeneratedTask {
  std::string name;  // fuzz-<seed>
  std::string domain;
  std::string problem;
  std::vector<std::string> features;  // the structures planted, by name
};

GeneratedTask generate_task(std::uint64_t seed, const GeneratorOptions& options = {});

}  // namespace alplan::differential
