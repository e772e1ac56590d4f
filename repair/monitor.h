// The execution monitor (the paper's Section 6.3, and its Discussion's
// proactive look-ahead): it executes a plan against a World, advancing time
// from happening to happening and by a step size between them; at every
// observation it checks the timeline against the observed state, and on a
// violated condition it stops and hands the failure record (the validator's
// Violation) to a repair strategy, then carries on with the repaired plan.
// Every run ends with the goal reached or with an explained failure.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pddl_parser/ast.h"
#include "repair/executing_plan.h"
#include "repair/explanation.h"
#include "repair/observation.h"
#include "repair/repair_strategy.h"
#include "repair/world.h"
#include "planner/planner.h"

namespace alplan::repair {

struct MonitorOptions {
  double step_size = 5.0;  // observations between happenings
  bool lookahead = true;   // report a failure as soon as it is certain
  int max_repairs = 5;
  // Proactive mode: whenever perception sees new objects, plan again and
  // switch if the plan ends at least `proactive_gain` earlier.
  bool proactive = false;
  double proactive_gain = 1.0;
  double proactive_budget = 0.25;  // seconds of anytime search per look
  PlannerOptions planner = executing_planner_options();  // for the proactive plans
  // Ground the mission's problem once, when execution starts, and let the
  // repairs reuse that grounding while the observed world stays within it
  // (planner/grounding_cache.h); off, every repair grounds from scratch.
  bool reuse_grounding = true;
  // What the monitor can see of the world (observation.h): it checks the
  // plan against its belief, not against the world's true state.
  ObservationOptions observation;
  // A failure foreseen by looking ahead that no repair can mend yet is not
  // final while its condition is not due: the robot carries on, and the
  // monitor tries again whenever it sees something new (the robot reaching
  // the room where a substitute stands) and once more when it falls due.
  bool defer_foreseen = true;
};

struct RepairRecord;

// What the monitor does, as it does it, for a log (the home's event log):
// plans adopted, snaps dispatched, failures and repairs, goals merged.
struct MonitorEvent {
  enum class Kind : unsigned char { Plan, ActionStart, ActionEnd, Failure, Repair, MergeFailed };
  Kind kind = Kind::Plan;
  double time = 0.0;
  std::string action;  // ActionStart, ActionEnd, Failure: the ground action
  // Plan: why it was adopted ("initial", "repair", "merge", "proactive");
  // MergeFailed: why the merged goals have no plan.
  std::string reason;
  const ExecutingPlan* plan = nullptr;   // Plan
  const RepairRecord* repair = nullptr;  // Failure (the failure part), Repair
  double planning_seconds = 0.0;         // Plan
};

// New goals that arrive while a plan runs (a home with many seniors): what
// the problem gains. The monitor plans the old goal and the new together
// from the observed state, committing to what is underway, and switches
// only when that plan exists.
struct GoalArrival {
  std::vector<pddl::Condition> goals;
  // Told, not seen: the senior is sad (true), no longer soothed (false), a
  // window is open.
  std::vector<std::pair<AtomKey, bool>> facts;
  std::vector<pddl::TimedInitialLiteral> timed_literals;  // windows closing
  // Literals no longer to come: the windows of goals settled since the last
  // arrival, which must not close a new window early.
  std::vector<pddl::TimedInitialLiteral> withdrawn;
  // PDDL 3 soft goals (a home's windows as preferences): when set, the
  // merged problem's constraints and metric become these.
  struct Preferences {
    std::optional<pddl::Condition> constraints;
    std::optional<pddl::Metric> metric;
  };
  std::optional<Preferences> preferences;
  std::string motivation;
};

// What the deliberation is about: the domain (with the ontology's types),
// what the problem knows, and why the goal matters.
struct Mission {
  const pddl::Domain* domain = nullptr;
  pddl::Problem problem;
  std::string motivation;   // "senior1 is terrified"
  std::string robot = "robot1";
  // Predicates the world changes outside the robot's actions (an object
  // becoming unavailable): ground as fluents, so that such a change needs
  // no new grounding (normalize.h).
  std::vector<std::string> exogenous_predicates;
  // Goal generation, re-invoked on every failure (the paper's step 3b): the
  // goal the observed state calls for and the reason, or nothing to keep
  // the current goal. Optional.
  std::function<std::optional<std::pair<pddl::Condition, std::string>>(const WorldState&)> goal_generator;
  // When the robot starts: the first observation is at the earlier of this
  // and the plan's first step.
  double start_time = 0.0;
  // Told of every MonitorEvent, in order. Optional.
  std::function<void(const MonitorEvent&)> on_event;
  // Asked at every observation, with what the robot believes then. Optional.
  std::function<std::optional<GoalArrival>(double t, const WorldState& observed)> arrivals;
  // The belief to keep: a home's, shared by its missions, so that what one
  // mission's robot learns (an object gone, a substitute recognised, a
  // sighting) is known to the next. None: the monitor keeps its own, made
  // from the problem with MonitorOptions::observation.
  Belief* belief = nullptr;
};

struct RepairRecord {
  Violation failure;
  bool foreseen = false;  // found by looking ahead
  // Not mended yet, but not due either: execution went on (defer_foreseen).
  bool deferred = false;
  // A step of the search for a person lost from sight (person_search.h):
  // the condition that failed was where the search guessed they were. It is
  // bounded by the home's places, so it does not count against max_repairs.
  bool search = false;
  std::string strategy;
  std::string fallback;  // what the strategy did instead, when it could not do its own (RepairResult)
  bool repaired = false;
  double seconds = 0.0;
  int planner_calls = 0;
  bool reused_grounding = false;
  std::string plan_text;  // the new plan, IPC format
  std::size_t plan_distance = 0;  // actions removed plus added (Fox et al. 2006)
  std::vector<RecognizedObject> integrated;
  double perception_seconds = 0.0;  // of `seconds`
  Explanation explanation;
};

struct ExecutionReport {
  std::string initial_plan_text;
  // Grounding the mission's problem when execution starts (reuse_grounding).
  double preparation_seconds = 0.0;
  std::vector<RepairRecord> repairs;
  bool goal_reached = false;
  double end_time = 0.0;
  std::string outcome;  // one sentence
  ObservationModel observation = ObservationModel::Iot;
  std::size_t sightings = 0;  // things the camera saw that the problem did not name
  // Its actions that came to nothing in the world (world.h, VoidAction): an
  // action started on a belief the world contradicted.
  std::size_t void_actions = 0;
  std::vector<std::string> events;  // what happened, in order, for people

  nlohmann::json json() const;
};

// One mission's execution, advanced by its caller one look at a time, so
// that a home can run several on one world (one robot's mission each),
// looking at each when it asks to be looked at. Monitor::run is the loop
// over it. The world and the strategy must outlive it; the options and the
// mission are copied (the mission's belief, when it brings one, is shared).
class MonitoredExecution {
 public:
  MonitoredExecution(const MonitorOptions& options, const Mission& mission, ExecutingPlan plan, World& world,
                     RepairStrategy& strategy, ObjectRecognizer* recognizer, const TypeOntology* ontology);
  ~MonitoredExecution();
  MonitoredExecution(const MonitoredExecution&) = delete;
  MonitoredExecution& operator=(const MonitoredExecution&) = delete;

  // When it first wants to look: the mission's start or the plan's first step.
  double first_look() const;
  // Observes at t (times never go back, across every execution on the
  // world), checks, repairs, takes in arrivals and dispatches what falls
  // due at t; returns when it wants to look next (after t), or nothing once
  // the run has ended, with the goal reached or an explained failure.
  std::optional<double> step(double t);
  bool ended() const;
  const ExecutionReport& report() const;
  const ExecutingPlan& plan() const;       // in force
  const pddl::Problem& problem() const;    // the plan's, as repairs and merges left it
  // The actions it started that the world still runs (a robot mid-move
  // when its mission is given up).
  std::vector<ActionInProgress> running() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

class Monitor {
 public:
  explicit Monitor(MonitorOptions options) : options_(options) {}

  ExecutionReport run(const Mission& mission, ExecutingPlan plan, World& world, RepairStrategy& strategy,
                      ObjectRecognizer* recognizer, const TypeOntology* ontology) const;

 private:
  MonitorOptions options_;
};

}  // namespace alplan::repair
