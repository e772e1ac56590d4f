// The grounded task: facts and numeric variables by id, ground actions with
// their at-start / over-all / at-end conditions and start / end effects (the
// snap actions of POPF), duration constraints, timed initial literals sorted
// by time, axioms by stratum, the goal and the metric.
//
// Contract: immutable once built (shared as std::shared_ptr<const
// GroundTask>); deterministic (the same files give the same ids). Conditions
// are conjunctions of literals and numeric comparisons, with general
// formulas kept only where a disjunction survives simplification.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/fact_table.h"
#include "planner/ids.h"
#include "planner/shared_vector.h"
#include "planner/normalized_task.h"

namespace alplan {

struct GroundExpression {
  enum class Kind : unsigned char {
    Constant, Variable, Add, Subtract, Multiply, Divide, Negate, Duration, TotalTime,
    Undefined,  // a static function term the problem gives no value
    IsViolated,  // (is-violated name): `variable` is the preference's index
  };
  Kind kind = Kind::Constant;
  double value = 0.0;
  NumericVarId variable = kNoId;  // Variable
  std::string undefined_term;     // Undefined, for messages
  std::vector<GroundExpression> operands;
};

// Appends the variables an expression reads (repeats kept).
void append_variables(const GroundExpression& e, std::vector<NumericVarId>& out);

struct GroundComparison {
  pddl::Comparison comparison = pddl::Comparison::Equal;
  GroundExpression left, right;
};

// A condition that did not reduce to a conjunction (a disjunction over
// fluents survived simplification).
struct GroundFormula {
  enum class Kind : unsigned char { True, False, Literal, Comparison, And, Or };
  Kind kind = Kind::True;
  FactId fact = kNoId;  // Literal
  bool positive = true;
  GroundComparison comparison;
  std::vector<GroundFormula> children;
  std::string reason;  // False: the instantiated condition that made it false
};

struct ConditionSet {
  std::vector<FactId> positive;
  std::vector<FactId> negative;
  std::vector<GroundComparison> numeric;
  std::vector<GroundFormula> complex;
  // Set when the condition can never hold, with the condition that fails.
  std::optional<std::string> never;
  // Fluent facts the lifted condition names that simplification dropped
  // (a disjunct beside a true static atom, a consequent under a false one).
  // They do not decide whether the condition holds, but VAL's mutex rule
  // counts every proposition a precondition names, so the planner orders
  // snaps by them too. Sorted; never in `positive` or `negative`.
  std::vector<FactId> mentioned;
  // Atoms the condition names that are no fact at all (never true, so the
  // grounding kept no id for them), as ids of GroundTask::ghosts. VAL's
  // mutex rule counts them too: a start reading (not f), f never true,
  // clashes with an end deleting f in one happening.
  std::vector<std::uint32_t> ghost_mentioned;
  // Numeric variables named where they decide nothing (a precondition
  // preference a round does not enforce): read, for VAL's mutex rule.
  std::vector<NumericVarId> mentioned_values;

  bool empty() const {
    return positive.empty() && negative.empty() && numeric.empty() && complex.empty() && !never;
  }
};

// Appends every fact and numeric variable a condition names, decided or
// only mentioned (literals, comparisons, complex formulas; repeats kept):
// what VAL's mutex rule counts as read. Ghost atoms are not included.
void append_reads(const ConditionSet& c, std::vector<FactId>& facts, std::vector<NumericVarId>& variables);

struct NumericAssignment {
  NumericVarId variable = kNoId;
  pddl::AssignOperator assign = pddl::AssignOperator::Assign;
  GroundExpression value;
};

struct ConditionalEffect {
  ConditionSet condition;
  Moment condition_moment = Moment::Start;
  std::vector<FactId> add, del;
  std::vector<std::uint32_t> ghost_del;  // deletes of atoms that are never facts (GroundTask::ghosts)
  std::vector<NumericAssignment> numeric;
};

struct HappeningEffects {
  std::vector<FactId> add, del;
  std::vector<std::uint32_t> ghost_del;  // deletes of atoms that are never facts (GroundTask::ghosts)
  std::vector<NumericAssignment> numeric;
  std::vector<ConditionalEffect> conditional;
  // Facts the unconditional effects add more than once (`add` holds each
  // once): VAL's mutex rule refuses a second add of a fact the action reads
  // when its happening has other members (happening_executor.cpp).
  std::vector<FactId> added_twice;

  bool empty() const { return add.empty() && del.empty() && numeric.empty() && conditional.empty(); }
};

struct GroundDurationConstraint {
  pddl::Comparison comparison = pddl::Comparison::Equal;
  GroundExpression value;
  Moment moment = Moment::Start;
};

// Linear continuous change while a durative action runs (PDDL 2.1 level 4):
// `variable` moves by `rate` per time unit (down for Decrease); the rate is
// evaluated in the state where the action starts.
struct ContinuousEffect {
  NumericVarId variable = kNoId;
  pddl::AssignOperator assign = pddl::AssignOperator::Increase;  // or Decrease
  GroundExpression rate;
};

// One instance of a PDDL 3 preference in the goal or an action's condition.
struct GroundPreference {
  std::uint32_t preference = 0;  // index into TrajectoryConstraints::preferences
  ConditionSet condition;
  pddl::TimeSpecifier time = pddl::TimeSpecifier::AtStart;
};

// One instance of a PDDL 3 trajectory constraint (trajectory_constraints.h).
struct GroundConstraint {
  ModalOperator op = ModalOperator::Always;
  ConditionSet requirement, trigger;
  double deadline = 0.0, from = 0.0;
  std::optional<std::uint32_t> preference;  // soft when set
  // Instances with one monitor count one violation between them (VAL).
  std::uint32_t monitor = 0;
  std::string text;  // as written, with the forall binding
};

struct GroundTrajectory {
  std::vector<GroundConstraint> constraints;
  std::vector<GroundPreference> goal_preferences;
  std::uint32_t monitors = 0;
  // Set on a task compiled from PDDL 3 (pddl3_compilation.h): why a search
  // of it exhausted proves nothing about the task it came from.
  std::vector<std::string> approximations;
};

struct GroundAction {
  std::uint32_t schema = 0;  // index into NormalizedTask::actions
  std::vector<ObjectId> args;
  bool durative = false;
  ConditionSet at_start, over_all, at_end;  // instantaneous: at_start
  HappeningEffects start, end;               // instantaneous: start
  std::vector<GroundDurationConstraint> duration;
  std::vector<ContinuousEffect> continuous;
  std::vector<GroundPreference> preferences;  // PDDL 3, beside the hard conditions
};

struct GroundAxiom {
  FactId head = kNoId;
  ConditionSet body;
  std::uint32_t stratum = 0;
};

struct GroundTimedLiteral {
  double time = 0.0;
  FactId fact = kNoId;
  bool positive = true;
};

struct GroundMetric {
  bool minimize = true;
  GroundExpression expression;
};

// Wall-clock seconds of each grounding pass.
struct GroundingTimes {
  double normalize = 0, reachability = 0, instantiate = 0, axioms = 0;
};

struct GroundTask {
  std::shared_ptr<const NormalizedTask> lifted;
  GroundKeyTable facts;    // head: PredicateId
  // Atoms some action deletes or some condition names that can never be
  // true (no fact): kept only for the footprints of VAL's mutex rule
  // (task_index.cpp). Head: PredicateId.
  GroundKeyTable ghosts;
  GroundKeyTable numeric;  // head: FunctionId
  std::vector<FactId> initial_facts;
  std::vector<double> initial_values;  // per numeric variable; NaN when undefined
  SharedVector<GroundAction> actions;  // shared by the tasks a GroundingCache derives
  std::vector<GroundAxiom> axioms;  // sorted by stratum
  std::uint32_t strata = 0;
  std::vector<GroundTimedLiteral> timed_literals;  // sorted by time
  ConditionSet goal;
  std::optional<GroundMetric> metric;
  GroundTrajectory pddl3;
  GroundingTimes times;

  std::string fact_name(FactId fact) const;
  std::string variable_name(NumericVarId variable) const;
  std::string action_name(const GroundAction& action) const;
  bool is_derived(FactId fact) const;
};

// Whether two tasks hold the very same ground actions (not equal copies)
// over tables of the same sizes and the same axioms' count: a grounding
// cache's derived tasks and their reference. Structures built from one
// task's actions then serve the other.
bool same_ground_actions(const GroundTask& a, const GroundTask& b);

}  // namespace alplan
