// Executes a scheduled plan happening by happening, with VAL's semantics
// (see validator.h). `step()` advances one happening, so a caller can watch
// the state between happenings; `run()` goes to the end and judges the goal.
// With ValidatorOptions::report_all it goes on after a violation as
// validator.h describes; an observer sees each happening as it is executed.
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <string>
#include <vector>

#include "planner/derived_support.h"
#include "planner/formula_evaluation.h"
#include "planner/explicit_state.h"
#include "planner/ground_task.h"
#include "planner/trajectory_monitor.h"
#include "planner/validation_result.h"
#include "planner/violation.h"

namespace alplan {

// A plan step bound to its ground action and its times.
struct ScheduledStep {
  std::size_t action = 0;  // index into GroundTask::actions
  std::size_t step = 0;    // index in the plan
  std::uint32_t line = 0;
  double start = 0.0;
  double duration = 0.0;   // durative actions only
  std::string name;        // "(act args)" as the plan wrote it
  // The action started before execution began (a plan made from an observed
  // state): its start is not executed, only its invariant and its end.
  bool started_before = false;
};

// Where execution begins when it is not the task's initial state: an
// observed state and the first timed literal still to come (earlier ones
// are in the past). Times stay the task's times.
struct ExecutionStart {
  ExplicitState state;
  std::size_t first_timed_literal = 0;
  double now = 0.0;
  // PDDL 3: the monitor of the states seen before `now`, over this
  // executor's task, which this run carries on; none, a fresh one.
  std::shared_ptr<const TrajectoryMonitor> trajectory;
};

class HappeningExecutor {
 public:
  HappeningExecutor(const GroundTask& task, const ValidatorOptions& options);

  // Whole-plan validation; `plan_steps` counts the lines for VAL's value.
  ValidationResult run(const std::vector<ScheduledStep>& steps, std::size_t plan_steps);
  ValidationResult run(const std::vector<ScheduledStep>& steps, std::size_t plan_steps, const ExecutionStart& start);

  // Step-wise use: load a schedule, then step until done() or a violation.
  void load(const std::vector<ScheduledStep>& steps);
  void load(const std::vector<ScheduledStep>& steps, const ExecutionStart& start);
  bool done() const { return next_ >= happenings_.size(); }
  // The first violation at the next happening, if any; with report_all,
  // step_violations() holds every one found there.
  std::optional<Violation> step();
  const std::vector<Violation>& step_violations() const { return step_violations_; }
  // Called after each happening that step() or run() executes.
  void set_observer(HappeningObserver observer) { observer_ = std::move(observer); }
  double time() const { return time_; }
  std::size_t happenings() const { return happenings_.size(); }
  const ExplicitState& state() const { return state_; }

 private:
  enum class Point : unsigned char { Start, End, Instant, Til };
  struct Event {
    Point point = Point::Instant;
    double time = 0.0;
    std::size_t scheduled = 0;  // index into steps_, or TIL index
  };
  struct Update {
    NumericVarId variable;
    pddl::AssignOperator assign;
    double value;
  };
  // What one event reads and writes, for the mutex check.
  struct Footprint {
    // Every fact read, against the other members of the happening (the
    // firing conditional effects' conditions included: happening_executor.cpp
    // says why even where VAL would not always count them).
    std::set<FactId> reads, adds, dels;
    // Facts this event reads before it changes them: a precondition, or a
    // firing condition's fact not yet added or deleted by it.
    std::set<FactId> claimed_reads;
    // Facts added after an earlier add or delete of them by the same event,
    // in the order VAL processes effects (adds, deletes, then each
    // conditional effect that fires).
    std::set<FactId> added_again;
    std::set<NumericVarId> reads_values;
    std::vector<std::pair<NumericVarId, pddl::AssignOperator>> writes;
  };

  ValidationResult finish_run(std::size_t plan_steps);
  // Executes the next happening; its violations go to step_violations_.
  void execute_happening();
  // Conditions, mutex, effects of one happening's members, at time_.
  void execute_members(const std::vector<Event>& events);
  // The invariants of the actions running after the happening just run.
  void check_running();
  // Records a violation; true when validation must stop there.
  bool record(std::optional<Violation> v);
  // Every goal condition unsatisfied in the final state (one with
  // report_all off), as GoalNotReached violations.
  std::vector<Violation> unmet_goals() const;
  // PDDL 3 preferences of an action's condition at `time`: each failing
  // instance counts one violation (over all: once per occurrence).
  void count_preferences(const Event& e, pddl::TimeSpecifier time, const ExplicitState& state);
  // The goal's preferences, the final state's constraints, the counts.
  std::optional<Violation> finish_trajectory(ValidationResult& result);
  std::optional<Violation> check_conditions(const Event& e);
  std::optional<Violation> check_mutex(const std::vector<Event>& events);
  std::optional<Violation> apply(const std::vector<Event>& events);
  // Every running action whose invariant fails in `state` (the first only,
  // without report_all) goes to step_violations_; true when one did.
  bool check_invariants(const ExplicitState& state, double at, double until);
  // Continuous change (PDDL 2.1 level 4): the rates an action runs with,
  // fixed in the state where it starts; `advance` moves the state along them.
  void start_rates(std::size_t scheduled, const ExplicitState& state);
  void advance(ExplicitState& state, double elapsed) const;
  Footprint footprint(const Event& e) const;
  std::string event_name(const Event& e) const;
  EvaluationContext context_of(const Event& e) const;
  const GroundAction* action_of(const Event& e) const;
  Violation violation(Violation::Kind kind, const Event& e) const;
  std::string explain(const EvaluationError& error) const;
  // An UndefinedValue violation of `what` at `time`, explained.
  Violation undefined_value(const EvaluationError& error, double time, const std::string& what) const;

  const GroundTask& task_;
  double epsilon_;
  bool val_total_time_;
  double numeric_slack_;
  bool report_all_;
  HappeningObserver observer_;
  std::vector<Violation> step_violations_;
  // The supports of derived facts, found as conditions on them are met.
  mutable std::unique_ptr<DerivedSupport> derived_;
  std::vector<ScheduledStep> steps_;
  std::vector<std::vector<Event>> happenings_;
  std::vector<double> happening_times_;
  std::size_t next_ = 0;
  double time_ = 0.0;
  ExplicitState state_;
  std::map<std::size_t, std::size_t> running_;  // scheduled step -> its action
  std::map<std::size_t, std::vector<std::pair<NumericVarId, double>>> rates_;  // scheduled step -> signed rates
  // The state right after the last happening that holds an action (VAL
  // evaluates the metric there, before any later timed literal).
  std::size_t last_action_happening_ = 0;
  std::optional<ExplicitState> last_action_state_;
  double last_action_time_ = 0.0;
  // PDDL 3 trajectory constraints and preference counts over this run.
  std::optional<TrajectoryMonitor> trajectory_;
  // (scheduled step, index among its action's preferences)
  std::set<std::pair<std::size_t, std::size_t>> invariant_preferences_counted_;
};

}  // namespace alplan
