// Repair strategies behind one interface, chosen by name, so that they can
// be compared on the same failures (bench repair):
// - replan: plan again from the observed state (the paper's step 3c);
// - substitute: integrate the new objects perception recognises, of the
//   types the ontology augments, then replan (the paper's Scenarios 1, 2);
// - suggest: go straight to suggesting an activity, no object handled
//   (the paper's Scenario 3 outcome, as a policy);
// - patch: keep the rest of the plan and swap the failed object for an
//   available one of the same supertype; replan only when that is invalid;
// - adapt: LPG-ADAPT's objective: the metric plus a penalty per action
//   added to or removed from the old plan's remaining steps (Fox et al.'s
//   distance), searched by anytime search on stable's compilation within a
//   budget (adapt_strategy.cpp);
// - stable: the plan at minimum distance from the old plan's remaining
//   steps (Saetti & Scala's compilation to cost-optimal planning,
//   stable_compilation.h), proven minimal when the search ends in budget.
// - switch: keep k diverse plans for the goal (planner/diverse_plans.h) and
//   switch to the best one still executable from the observed state;
//   replan only when none is.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/grounding_cache.h"
#include "planner/planner.h"
#include "planner/violation.h"
#include "repair/executing_plan.h"
#include "repair/object_recognizer.h"
#include "repair/type_ontology.h"
#include "repair/world.h"

namespace alplan::repair {

// Planner options for plans a robot executes under the monitor: as the
// planner's, without deordering (planner/plan_deordering.h). A deordered
// plan may start a step at the instant the step it needs ends, where VAL
// allows it (an invariant is no start condition); the monitor's world runs
// one happening's members in some order, and the paper's figures are
// OPTIC's schedules, which keep one epsilon there.
inline PlannerOptions executing_planner_options() {
  PlannerOptions options;
  options.deorder = false;
  return options;
}

struct StrategyOptions {
  PlannerOptions planner = executing_planner_options();
  // Schemas that hand an object over; `suggest` plans without them.
  std::set<std::string> handling_actions{"carry", "fill", "give"};
  // `adapt` minimises the problem's metric (the makespan without one) plus
  // adapt_penalty times the plan distance from the old plan's remaining
  // steps: each action added and each old step removed, per occurrence.
  // The penalty is a change's price in units of the metric (a second of
  // makespan, a unit of cost). adapt_budget: seconds of search (grounding
  // the compiled task comes on top).
  double adapt_penalty = 100.0;
  double adapt_budget = 0.25;  // seconds
  // The lowest anytime weight adapt looks for closer plans with: on the
  // generated homes of bench repair, weights 2, 1.5 and 1 found no better
  // plan in 57 repairs and took 60% of the time.
  double adapt_min_weight = 3.0;
  // Expansions each anytime weight may spend looking for a closer plan
  // (with_anytime, search_configuration.h); 0: until proven.
  std::uint64_t adapt_expansions = 0;
  // `stable`: seconds for the searches of the compiled task (grounding
  // aside), and the share of them the complete search that proves a
  // repair minimal may take; the rest looks for any close repair when it
  // does not finish.
  double stable_budget = 5.0;
  double stable_proof_share = 0.8;
  // The search that proves: complete and ordered by the metric with an
  // admissible heuristic (stable_strategy.cpp says why its first plan is
  // then minimal). A* on landmark cuts proved 56 of 111 repairs minimal on
  // the IPC stability testbed's instances 1-5 where uniform-cost search
  // (blind) proved 9 (benchmarks/README.md).
  std::string stable_proof_search = "complete(wastar(lmcut, w=1, order=metric, preferred=false))";
  // `switch`: how many diverse plans it keeps per goal, how far apart
  // (actions, planner/diverse_plans.h), and each one's search budget
  // (expansions keep the set the same on a loaded machine; seconds cap it).
  std::size_t switch_plans = 3;
  std::size_t switch_min_distance = 2;
  std::size_t switch_expansions = 20000;
  double switch_budget = 1.0;  // seconds per plan
};

struct RepairRequest {
  const pddl::Domain* domain = nullptr;    // augmented with the ontology's types
  const pddl::Problem* problem = nullptr;  // the objects known so far, TILs, goal, metric
  const ExecutingPlan* plan = nullptr;     // the plan that failed
  const Violation* failure = nullptr;
  WorldState observed;
  std::vector<ActionInProgress> in_progress;
  double now = 0.0;
  std::string robot_location;              // where the camera looks
  ObjectRecognizer* recognizer = nullptr;  // may be absent
  // What the camera saw on the way that the problem does not name (the
  // monitor's belief): a substitute may stand in a room passed earlier.
  std::vector<Sighting> sightings;
  const TypeOntology* ontology = nullptr;  // may be absent
  // The execution's grounding, reused when the reformulated problem fits it
  // (grounding_cache.h); may be absent, and then every repair grounds anew.
  GroundingCache* grounding = nullptr;
  // What the monitor believed at each change before `now`, oldest first:
  // the trajectory so far, which PDDL 3 constraints judge (planner.h,
  // PlanningStart::history). Kept only for problems with constraints.
  const std::vector<WorldState>* history = nullptr;
};

struct RepairResult {
  bool repaired = false;
  std::optional<ExecutingPlan> plan;
  pddl::Problem problem;                 // what the new plan solves (new objects in it)
  std::vector<RecognizedObject> integrated;
  std::string how;                       // the third part of the explanation
  int planner_calls = 0;
  double seconds = 0.0;
  bool reused_grounding = false;  // no grounding of its own was needed
  // The strategy could not do what it is named for and did something else
  // instead (adapt without action costs replans): that other's name.
  std::string fallback;
  // The part of `seconds` spent asking perception what the camera saw.
  double perception_seconds = 0.0;
  // The plan's distance from the old plan is proven minimal (stable, when
  // its proof search finished and names no limit): what a cross-check may
  // compare a proven distance with.
  bool proven_minimal = false;
};

class RepairStrategy {
 public:
  virtual ~RepairStrategy() = default;
  virtual std::string name() const = 0;
  virtual RepairResult repair(const RepairRequest& request) = 0;
};

// Throws std::invalid_argument for an unknown name.
std::unique_ptr<RepairStrategy> make_strategy(const std::string& name, const StrategyOptions& options);
std::vector<std::string> strategy_names();
// The names as a list for help and messages: "replan, substitute, ...".
std::string strategy_list();

// Shared by the strategies: reformulate from the observed state and plan.
// `excluded`: schemas whose actions the new plan may not use.
RepairResult replan_from(const RepairRequest& request, const pddl::Domain& domain, const pddl::Problem& problem,
                         const PlannerOptions& options, const std::set<std::string>& excluded = {});
// Validates a plan bound to a reformulated task (reformulation.h) from
// that task's initial state -- the observed one, actions in progress
// committed as timed literals -- at `now`, its steps at their times.
ValidationResult validate_from_now(const ExecutingPlan& plan, double now);
// A plan mapped back from a compiled task (stable_compilation.h), in time
// order, bound to the reformulated `task` and validated there from `now`;
// nullopt, with the reason in `why`, when it does not bind or is not valid.
std::optional<ExecutingPlan> bind_validated(const std::shared_ptr<const GroundTask>& task, Plan plan, double now,
                                            double epsilon, std::string& why);
// Adds the objects perception recognises at the robot's location and among
// the things the camera saw on the way (the request's sightings, each where
// it was seen), of types the domain knows, to the problem, and what perception saw of them -- (be o
// location) and (available o) -- to the request's observed state (the
// paper: "integrated into the planning problem along with its location and
// availability"; IoT sensors know nothing of such objects); returns them.
std::vector<RecognizedObject> integrate_recognized(RepairRequest& request, pddl::Problem& problem);
// A sentence naming what the new plan gives or suggests, to whom.
std::string describe_remedy(const ExecutingPlan& plan, double from);

}  // namespace alplan::repair
