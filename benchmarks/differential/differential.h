// The differential tester: random tasks (task_generator.h) given to the
// planner and to a brute force (brute_force.h) that asks the reference
// semantics (oracle/), which shares no code with the planner.
//
// Each task ends in one class:
//  agree_solved         the planner's plan is valid, and the brute force
//                       found a plan too;
//  agree_solved_late    the same, but the planner reached its first limit
//                       and found the plan within the generous one
//                       (retry_time_limit), asked for only where the brute
//                       force found a plan;
//  planner_only_solved  the planner's plan is valid; the brute force
//                       exhausted its bound without one (the plan is longer
//                       or its times lie outside the bound);
//  agree_unsolvable     the planner proved "no plan", and the brute force
//                       exhausted its bound without one;
//  agree_unsolved       the planner gave up (no proof), and the brute force
//                       exhausted its bound without one;
//  undecided            the brute force was cut short where its answer was
//                       needed: never counted as agreement;
//  missed_val_order_only  the planner found no plan, and every plan the
//                       brute force finds in its bound is valid only by the
//                       order in which VAL claims a happening's facts (the
//                       symmetric mutex rule, oracle/ownership.h, refuses
//                       them all): printed apart, never counted as agreement
//                       nor as a disagreement;
//  missed_sub_epsilon_only  the planner found no plan (no proof), and every
//                       plan the brute force finds in its bound, under the
//                       symmetric rule, puts two interfering happenings
//                       closer than epsilon (a timed literal 0.0005 after an
//                       end that reads what it deletes): a planner that
//                       separates interfering happenings by epsilon cannot
//                       produce one (oracle/judge.h, epsilon_separation);
//                       printed apart like the class above;
// or in a disagreement:
//  invalid_plan         the reference semantics rejects the planner's plan;
//  unjudged_plan        it cannot judge it (an undefined value is read);
//  false_unsolvable     the planner said "no plan exists", the brute force
//                       found one;
//  missed_plan          the planner gave up (search exhausted, or a limit)
//                       on a task the brute force solves;
//  internal_error, unsupported, crash, generator_error.
// A task is non-trivial when it is solvable only with two steps or more
// (no plan of one step exists), or unsolvable for a reason other than
// grounding.
// Task k of a run with seed s is generate_task(task_seed(s, k)), with
// task_seed(s, k) = s * 2^32 + k: runs with different seeds (below 2^32) draw
// disjoint tasks, so seeds 1, 2 and 3 are three samples, not one sample
// shifted by a task. A disagreement names its task seed;
// `alplan fuzz planner --task-seed N` replays that one task.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "benchmarks/differential/brute_force.h"
#include "benchmarks/differential/task_generator.h"

namespace alplan::differential {

struct DifferentialOptions {
  std::uint64_t tasks = 100;
  std::uint64_t seed = 1;
  // When set, the run is this one task (generate_task(*task_seed)) and
  // `tasks` and `seed` are not used.
  std::optional<std::uint64_t> task_seed;
  // Stops after this many seconds even if tasks remain (CI's minute).
  double seconds = std::numeric_limits<double>::infinity();
  // Per task, for the planner: generous against the tasks' size (no more
  // than five ground actions; the brute force's search takes a tenth of it).
  double planner_time_limit = 2.0;
  // Where the brute force finds a plan and the planner reached its limit,
  // the planner runs again with this one before a miss is called: a plan
  // missed is one missed within a generous limit (issue 42: the IPC runs'
  // 60 s), and the unsolvable tasks, most of the run, keep the short one.
  double retry_time_limit = 60.0;
  std::size_t planner_node_limit = 200000;
  GeneratorOptions generator;
  BruteForceOptions brute_force;
  std::string out_dir;  // where each disagreeing task is written ("": nowhere)
  std::string all_dir;  // where every task is written, with its class ("": nowhere)
  bool shrink = true;   // reduce each disagreeing task before writing it
  int jobs = 1;         // tasks checked at once, each in its own thread
};

// The seed task k of a run with seed `run_seed` is generated from.
std::uint64_t task_seed(std::uint64_t run_seed, std::uint64_t k);

struct Disagreement {
  std::uint64_t seed = 0;  // the task's seed (task_seed), as --task-seed takes it
  std::string kind;
  std::string planner_status;  // as status_name() prints it
  std::string message;
  std::string plan;  // the planner's (invalid_plan) or the brute force's
  std::string domain, problem;
  std::vector<std::string> features;
};

struct ClassCounts {
  std::uint64_t tasks = 0, non_trivial = 0;
  double seconds = 0.0;  // spent checking these tasks (planner, brute force, shrinking)
};

struct DifferentialReport {
  std::uint64_t tasks = 0;
  std::map<std::string, ClassCounts> by_class;    // agree_solved, ..., and each disagreement kind
  std::map<std::string, ClassCounts> by_feature;  // tasks with each planted structure
  std::uint64_t judgements = 0;
  double seconds = 0.0;
  std::string bound;
  std::string planner_limits;
  std::vector<Disagreement> disagreements;
  std::uint64_t count(const std::string& cls) const {
    auto it = by_class.find(cls);
    return it == by_class.end() ? 0 : it->second.tasks;
  }
};

// One task: its class (and, for a disagreement, the record).
struct TaskOutcome {
  std::string cls;
  bool non_trivial = false;
  std::uint64_t judgements = 0;
  std::string planner_plan, witness;  // the planner's plan, the brute force's (when there is one)
  std::optional<Disagreement> disagreement;
  double seconds = 0.0;
};
TaskOutcome check_task(const std::string& domain, const std::string& problem, const DifferentialOptions& options);

DifferentialReport run_differential(const DifferentialOptions& options, std::ostream& progress);

// One line per class and feature, and one paragraph per disagreement.
void print_report(const DifferentialReport& report, std::ostream& out);

// The same as one JSON object (what benchmarks/readme_figures.py reads):
// tasks, seconds, judgements, bound, planner_limits, undecided,
// disagreements (a count), classes and features ({name: {tasks,
// non_trivial, seconds}}), and findings (each disagreement).
void write_report_json(const DifferentialReport& report, std::ostream& out);

// shrink.cpp. Reduces a task on which the planner and the reference semantics disagree:
// drops actions, conditions, effects, initial facts, timed literals, goals
// and constraints one at a time, keeping each drop after which the same
// disagreement remains (delta debugging's one-minimal reduction: Zeller &
// Hildebrandt, "Simplifying and Isolating Failure-Inducing Input", IEEE TSE
// 28(2), 2002, with single-element steps), until no drop keeps it.
Disagreement shrink(const Disagreement& found, const DifferentialOptions& options);

}  // namespace alplan::differential
