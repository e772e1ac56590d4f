#include "planner/happening_executor.h"

#include <algorithm>
#include <cmath>

#include "pddl_parser/writer.h"
#include "planner/continuous_change.h"
#include "planner/formula_evaluation.h"
#include "planner/ground_printer.h"
#include "planner/happening_effects.h"

namespace alplan {
namespace {

// The sum of action costs, when the domain declares (total-cost): its value
// in `state`, or its initial value when no action changes it (grounding then
// keeps no variable for it).
std::optional<double> total_cost(const GroundTask& task, const ExplicitState& state) {
  const NormalizedTask& lifted = *task.lifted;
  for (FunctionId f = 0; f < lifted.functions.size(); ++f) {
    if (lifted.functions[f].name != "total-cost") continue;
    if (const std::optional<NumericVarId> v = task.numeric.find({f, {}})) return state.value(*v);
    for (const NumericInitialValue& initial : lifted.initial_values) {
      if (initial.function == f && initial.args.empty()) return initial.value;
    }
    return std::nullopt;
  }
  return std::nullopt;
}

void collect_facts(const GroundFormula& f, std::set<FactId>& out) {
  if (f.kind == GroundFormula::Kind::Literal) out.insert(f.fact);
  for (const GroundFormula& child : f.children) collect_facts(child, out);
}

void collect_variables(const GroundExpression& e, std::set<NumericVarId>& out) {
  if (e.kind == GroundExpression::Kind::Variable) out.insert(e.variable);
  for (const GroundExpression& operand : e.operands) collect_variables(operand, out);
}

void collect_variables(const GroundFormula& f, std::set<NumericVarId>& out) {
  if (f.kind == GroundFormula::Kind::Comparison) {
    collect_variables(f.comparison.left, out);
    collect_variables(f.comparison.right, out);
  }
  for (const GroundFormula& child : f.children) collect_variables(child, out);
}

// Atoms and values named where they decide nothing (ConditionSet::mentioned:
// simplified away, or a precondition preference a round of the preference
// search leaves out) count too: VAL reads every proposition a precondition
// names (the differential tester's task 8589948526, a dropped preference's
// read with a fact added twice).
void collect_reads(const ConditionSet& c, std::set<FactId>& facts, std::set<NumericVarId>& values) {
  facts.insert(c.positive.begin(), c.positive.end());
  facts.insert(c.negative.begin(), c.negative.end());
  facts.insert(c.mentioned.begin(), c.mentioned.end());
  values.insert(c.mentioned_values.begin(), c.mentioned_values.end());
  for (const GroundComparison& cmp : c.numeric) {
    collect_variables(cmp.left, values);
    collect_variables(cmp.right, values);
  }
  for (const GroundFormula& f : c.complex) {
    collect_facts(f, facts);
    collect_variables(f, values);
  }
}

bool additive(pddl::AssignOperator op) {
  return op == pddl::AssignOperator::Increase || op == pddl::AssignOperator::Decrease;
}

}  // namespace

std::string HappeningExecutor::explain(const EvaluationError& error) const {
  if (error.variable() == kNoId) return error.what();
  return "the value of " + task_.variable_name(error.variable()) + " is undefined";
}

Violation HappeningExecutor::undefined_value(const EvaluationError& error, double time, const std::string& what) const {
  Violation v;
  v.kind = Violation::Kind::UndefinedValue;
  v.time = time;
  v.action = what;
  v.condition = explain(error);
  return v;
}

HappeningExecutor::HappeningExecutor(const GroundTask& task, const ValidatorOptions& options)
    : task_(task), epsilon_(options.epsilon), val_total_time_(options.val_total_time), numeric_slack_(options.numeric_slack) {}

const GroundAction* HappeningExecutor::action_of(const Event& e) const {
  if (e.point == Point::Til) return nullptr;
  return &task_.actions[steps_[e.scheduled].action];
}

std::string HappeningExecutor::event_name(const Event& e) const {
  switch (e.point) {
    case Point::Start: return steps_[e.scheduled].name + " - start";
    case Point::End: return steps_[e.scheduled].name + " - end";
    case Point::Instant: return steps_[e.scheduled].name;
    case Point::Til: {
      const GroundTimedLiteral& til = task_.timed_literals[e.scheduled];
      const std::string fact = task_.fact_name(til.fact);
      return "(timed initial literal " + (til.positive ? fact : "(not " + fact + ")") + ")";
    }
  }
  return "?";
}

EvaluationContext HappeningExecutor::context_of(const Event& e) const {
  EvaluationContext context;
  if (e.point != Point::Til) context.duration = steps_[e.scheduled].duration;
  return context;
}

Violation HappeningExecutor::violation(Violation::Kind kind, const Event& e) const {
  Violation v;
  v.kind = kind;
  v.time = time_;
  v.action = event_name(e);
  if (e.point != Point::Til) {
    v.step = steps_[e.scheduled].step;
    v.line = steps_[e.scheduled].line;
  }
  return v;
}

void HappeningExecutor::load(const std::vector<ScheduledStep>& steps) {
  ExecutionStart start;
  start.state = ExplicitState::of(task_.initial_facts, task_.initial_values);
  load(steps, start);
}

void HappeningExecutor::load(const std::vector<ScheduledStep>& steps, const ExecutionStart& start) {
  steps_ = steps;
  std::vector<Event> events;
  for (std::size_t s = 0; s < steps_.size(); ++s) {
    const bool durative = task_.actions[steps_[s].action].durative;
    if (durative) {
      if (!steps_[s].started_before) events.push_back({Point::Start, steps_[s].start, s});
      events.push_back({Point::End, steps_[s].start + steps_[s].duration, s});
    } else {
      events.push_back({Point::Instant, steps_[s].start, s});
    }
  }
  for (std::size_t t = start.first_timed_literal; t < task_.timed_literals.size(); ++t) {
    events.push_back({Point::Til, task_.timed_literals[t].time, t});
  }
  std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.time < b.time; });
  // A happening takes every point within epsilon/10 of its first point.
  happenings_.clear();
  happening_times_.clear();
  for (std::size_t i = 0; i < events.size();) {
    const double first = events[i].time;
    std::vector<Event> group;
    while (i < events.size() && events[i].time <= first + epsilon_ / 10.0) group.push_back(events[i++]);
    happenings_.push_back(std::move(group));
    happening_times_.push_back(first);
  }
  last_action_happening_ = 0;
  for (std::size_t h = 0; h < happenings_.size(); ++h) {
    for (const Event& e : happenings_[h]) {
      if (e.point != Point::Til) last_action_happening_ = h;
    }
  }
  state_ = start.state;
  derive(task_, state_);
  running_.clear();
  rates_.clear();
  for (std::size_t s = 0; s < steps_.size(); ++s) {
    if (!steps_[s].started_before) continue;
    running_.emplace(s, steps_[s].action);
    try {
      start_rates(s, state_);
    } catch (const EvaluationError&) {
      // An undefined rate of an action already running: its change is
      // unknown; the validator then sees none (the observed state is what
      // counts at the next happening).
    }
  }
  next_ = 0;
  time_ = start.now;
  if (start.trajectory) {
    trajectory_.emplace(*start.trajectory);
  } else {
    trajectory_.emplace(task_, numeric_slack_);
  }
  invariant_preferences_counted_.clear();
  last_action_state_.reset();
  last_action_time_ = 0.0;
}

std::optional<Violation> HappeningExecutor::check_conditions(const Event& e) {
  const GroundAction* action = action_of(e);
  if (!action) return std::nullopt;
  const EvaluationContext context = context_of(e);
  const Moment moment = e.point == Point::End ? Moment::End : Moment::Start;
  if (e.point != Point::Instant) {
    for (const GroundDurationConstraint& d : action->duration) {
      if (d.moment != moment) continue;
      const double bound = evaluate(d.value, state_, context);
      const double given = steps_[e.scheduled].duration;
      const bool ok = d.comparison == pddl::Comparison::Equal          ? std::fabs(given - bound) < epsilon_
                      : d.comparison == pddl::Comparison::LessEqual    ? given - bound <= epsilon_
                      : d.comparison == pddl::Comparison::GreaterEqual ? bound - given <= epsilon_
                                                                        : true;
      if (!ok) {
        Violation v = violation(Violation::Kind::DurationViolation, e);
        v.condition = "[" + pddl::format_number(given) + "] against (" + pddl::to_string(d.comparison) +
                      " ?duration " + pddl::format_number(bound) + ")";
        return v;
      }
    }
  }
  const ConditionSet& condition = e.point == Point::End ? action->at_end : action->at_start;
  if (auto failed = first_unsatisfied(condition, state_, context, numeric_slack_)) {
    Violation v = violation(Violation::Kind::UnsatisfiedPrecondition, e);
    v.condition = describe(task_, condition, *failed);
    return v;
  }
  count_preferences(e, e.point == Point::End ? pddl::TimeSpecifier::AtEnd : pddl::TimeSpecifier::AtStart, state_);
  return std::nullopt;
}

void HappeningExecutor::count_preferences(const Event& e, pddl::TimeSpecifier time, const ExplicitState& state) {
  const GroundAction* action = action_of(e);
  if (!action || action->preferences.empty()) return;
  // An over-all preference is checked at every happening its action spans
  // but violated at most once per step: each of the step's over-all
  // preference instances (a forall gives several of one name) counts once,
  // each violated one counting (Gerevini & Long 2005, as at start and end).
  const bool invariant = time == pddl::TimeSpecifier::OverAll;
  for (std::size_t i = 0; i < action->preferences.size(); ++i) {
    const GroundPreference& p = action->preferences[i];
    if (p.time != time) continue;
    if (invariant && invariant_preferences_counted_.count({e.scheduled, i})) continue;
    if (holds(p.condition, state, context_of(e), numeric_slack_)) continue;
    trajectory_->count(p.preference);
    if (invariant) invariant_preferences_counted_.insert({e.scheduled, i});
  }
}

HappeningExecutor::Footprint HappeningExecutor::footprint(const Event& e) const {
  Footprint f;
  if (e.point == Point::Til) {
    const GroundTimedLiteral& til = task_.timed_literals[e.scheduled];
    (til.positive ? f.adds : f.dels).insert(til.fact);
    return f;
  }
  const GroundAction& action = *action_of(e);
  collect_reads(e.point == Point::End ? action.at_end : action.at_start, f.reads, f.reads_values);
  // VAL's mutex rule reads the propositions of preferences too.
  const pddl::TimeSpecifier at = e.point == Point::End ? pddl::TimeSpecifier::AtEnd : pddl::TimeSpecifier::AtStart;
  for (const GroundPreference& p : action.preferences) {
    if (p.time == at) collect_reads(p.condition, f.reads, f.reads_values);
  }
  // A condition on a derived fact reads what it is derived from (VAL).
  auto expand_derived = [&](std::set<FactId>& reads, std::set<NumericVarId>& values) {
    if (task_.axioms.empty()) return;
    if (!derived_) derived_ = std::make_unique<DerivedSupport>(task_);
    const std::vector<FactId> read(reads.begin(), reads.end());
    for (FactId p : read) {
      if (!task_.is_derived(p)) continue;
      const DerivedSupport::Support& s = derived_->of(p);
      reads.insert(s.facts.begin(), s.facts.end());
      values.insert(s.variables.begin(), s.variables.end());
    }
  };
  expand_derived(f.reads, f.reads_values);
  for (const GroundDurationConstraint& d : action.duration) collect_variables(d.value, f.reads_values);
  const HappeningEffects& effects = e.point == Point::End ? action.end : action.start;
  const EvaluationContext context = context_of(e);
  std::set<FactId> changed;  // by this event so far, in VAL's order
  f.claimed_reads = f.reads;
  f.added_again.insert(effects.added_twice.begin(), effects.added_twice.end());
  auto add_effects = [&](const std::vector<FactId>& adds, const std::vector<FactId>& dels,
                         const std::vector<NumericAssignment>& numeric) {
    for (FactId p : adds) {
      if (!changed.insert(p).second) f.added_again.insert(p);
    }
    changed.insert(dels.begin(), dels.end());
    f.adds.insert(adds.begin(), adds.end());
    f.dels.insert(dels.begin(), dels.end());
    for (const NumericAssignment& a : numeric) {
      collect_variables(a.value, f.reads_values);
      f.writes.emplace_back(a.variable, a.assign);
    }
  };
  add_effects(effects.add, effects.del, effects.numeric);
  for (const ConditionalEffect& c : effects.conditional) {
    if (!holds(c.condition, state_, context, numeric_slack_)) continue;
    // VAL claims a firing condition's reads when it constructs that effect
    // (Action::handleEffects): a fact this event has not yet changed is
    // claimed as read, and adding it twice afterwards is the added-and-read
    // mutex. One it has changed stays owned as written, so whether another
    // member's write of it is a mutex depends on which of the two the plan
    // lists first (VAL 3c7a1f3 refuses `0: (n)`, `0: (m)` and accepts
    // `0: (m)`, `0: (n)` where m deletes p and reads it in a conditional
    // effect and n deletes it). A plan's listing order is no part of its
    // meaning: every fact a firing condition reads counts as a read against
    // the other members, so what passes here passes VAL in any order.
    std::set<FactId> condition_reads;
    collect_reads(c.condition, condition_reads, f.reads_values);
    expand_derived(condition_reads, f.reads_values);
    for (FactId p : condition_reads) {
      f.reads.insert(p);
      if (!changed.count(p)) f.claimed_reads.insert(p);
    }
    add_effects(c.add, c.del, c.numeric);
  }
  return f;
}

std::optional<Violation> HappeningExecutor::check_mutex(const std::vector<Event>& events) {
  std::vector<Footprint> prints;
  for (const Event& e : events) prints.push_back(footprint(e));
  auto clash = [&](std::size_t a, std::size_t b, std::string what) {
    Violation v = violation(Violation::Kind::MutexViolation, events[a]);
    v.condition = std::move(what);
    v.other_action = event_name(events[b]);
    return v;
  };
  for (std::size_t a = 0; a < events.size(); ++a) {
    const Footprint& fa = prints[a];
    // VAL marks what an action reads only when its happening has other
    // members; a second add of such a fact by the same action then finds
    // it owned as added-and-read and is a mutex (Ownership::ownsForAdd).
    for (FactId p : fa.added_again) {
      if (events.size() > 1 && fa.claimed_reads.count(p)) {
        return clash(a, a, "adds " + task_.fact_name(p) + " twice while it reads it, with other members in its happening");
      }
    }
    for (std::size_t i = 0; i < fa.writes.size(); ++i) {
      for (std::size_t j = i + 1; j < fa.writes.size(); ++j) {
        if (fa.writes[i].first == fa.writes[j].first && !(additive(fa.writes[i].second) && additive(fa.writes[j].second))) {
          return clash(a, a, "assigns to " + task_.variable_name(fa.writes[i].first) + " twice");
        }
      }
    }
    for (std::size_t b = 0; b < events.size(); ++b) {
      if (a == b) continue;
      const Footprint& fb = prints[b];
      for (FactId p : fa.reads) {
        if (fb.adds.count(p)) return clash(b, a, "adds " + task_.fact_name(p) + ", which the other requires");
        if (fb.dels.count(p)) return clash(b, a, "deletes " + task_.fact_name(p) + ", which the other requires");
      }
      for (FactId p : fa.adds) {
        if (fb.dels.count(p)) return clash(a, b, "adds " + task_.fact_name(p) + ", which the other deletes");
      }
      for (const auto& [variable, op] : fb.writes) {
        if (fa.reads_values.count(variable)) {
          return clash(b, a, "changes " + task_.variable_name(variable) + ", which the other reads");
        }
        for (const auto& [other, other_op] : fa.writes) {
          if (other == variable && !(additive(op) && additive(other_op))) {
            return clash(b, a, "changes " + task_.variable_name(variable) + ", which the other also changes");
          }
        }
      }
    }
  }
  return std::nullopt;
}

std::optional<Violation> HappeningExecutor::apply(const std::vector<Event>& events) {
  std::vector<FactId> adds, dels;
  std::vector<Update> updates;
  for (const Event& e : events) {
    if (e.point == Point::Til) {
      const GroundTimedLiteral& til = task_.timed_literals[e.scheduled];
      (til.positive ? adds : dels).push_back(til.fact);
      continue;
    }
    const GroundAction& action = *action_of(e);
    const HappeningEffects& effects = e.point == Point::End ? action.end : action.start;
    const EvaluationContext context = context_of(e);
    auto collect = [&](const std::vector<FactId>& a, const std::vector<FactId>& d,
                       const std::vector<NumericAssignment>& numeric) {
      adds.insert(adds.end(), a.begin(), a.end());
      dels.insert(dels.end(), d.begin(), d.end());
      for (const NumericAssignment& n : numeric) {
        updates.push_back({n.variable, n.assign, evaluate(n.value, state_, context)});
      }
    };
    collect(effects.add, effects.del, effects.numeric);
    for (const ConditionalEffect& c : effects.conditional) {
      if (holds(c.condition, state_, context, numeric_slack_)) collect(c.add, c.del, c.numeric);
    }
  }
  for (FactId f : dels) state_.set_fact(f, false);
  for (FactId f : adds) state_.set_fact(f, true);
  for (const Update& u : updates) state_.set_value(u.variable, updated_value(state_.value(u.variable), u.assign, u.value));
  derive(task_, state_);
  return std::nullopt;
}

void HappeningExecutor::start_rates(std::size_t scheduled, const ExplicitState& state) {
  const GroundAction& action = task_.actions[steps_[scheduled].action];
  if (action.continuous.empty()) return;
  rates_[scheduled] = signed_rates(action, state, steps_[scheduled].duration);
}

void HappeningExecutor::advance(ExplicitState& state, double elapsed) const {
  if (elapsed <= 0.0) return;
  for (const auto& [scheduled, rates] : rates_) {
    for (const auto& [variable, rate] : rates) {
      const double current = state.value(variable);
      state.set_value(variable, (std::isnan(current) ? 0.0 : current) + rate * elapsed);
    }
  }
}

std::optional<Violation> HappeningExecutor::check_invariants(const ExplicitState& state, double at, double until) {
  for (const auto& [scheduled, action] : running_) {
    const ConditionSet& invariant = task_.actions[action].over_all;
    count_preferences({Point::Start, at, scheduled}, pddl::TimeSpecifier::OverAll, state);
    if (invariant.empty()) continue;
    EvaluationContext context;
    context.duration = steps_[scheduled].duration;
    if (auto failed = first_unsatisfied(invariant, state, context, rates_.empty() ? 0.0 : numeric_slack_)) {
      Violation v;
      v.kind = Violation::Kind::UnsatisfiedInvariant;
      v.time = at;
      v.until = until;
      v.action = steps_[scheduled].name;
      v.step = steps_[scheduled].step;
      v.line = steps_[scheduled].line;
      v.condition = describe(task_, invariant, *failed);
      return v;
    }
  }
  return std::nullopt;
}

std::optional<Violation> HappeningExecutor::step() {
  // VAL checks trajectory constraints in the state before each happening:
  // the initial state, then each happening's result but the last (finish_run).
  auto observe = [&]() -> std::optional<Violation> {
    try {
      return trajectory_->observe(state_, time_);
    } catch (const EvaluationError& error) {
      return undefined_value(error, time_, "the PDDL 3 constraints");
    }
  };
  if (next_ == 0 && trajectory_->active()) {
    if (auto v = observe()) return v;
  }
  if (auto v = execute_happening()) return v;
  if (!done() && trajectory_->active()) return observe();
  return std::nullopt;
}

std::optional<Violation> HappeningExecutor::execute_happening() {
  const std::vector<Event>& events = happenings_[next_];
  advance(state_, happening_times_[next_] - time_);
  time_ = happening_times_[next_];
  ++next_;
  const Event* current = &events.front();
  try {
    for (const Event& e : events) {
      current = &e;
      if (auto v = check_conditions(e)) return v;
    }
    current = &events.front();
    // With one member too: VAL refuses an action that assigns a value twice.
    if (auto v = check_mutex(events)) return v;
    for (const Event& e : events) {
      current = &e;
      if (e.point == Point::Start) start_rates(e.scheduled, state_);
    }
    current = &events.front();
    if (auto v = apply(events)) return v;
  } catch (const EvaluationError& error) {
    Violation v = violation(Violation::Kind::UndefinedValue, *current);
    v.condition = explain(error);
    return v;
  }
  for (const Event& e : events) {
    if (e.point == Point::End) {
      running_.erase(e.scheduled);
      rates_.erase(e.scheduled);
    }
  }
  for (const Event& e : events) {
    if (e.point == Point::Start) running_.emplace(e.scheduled, steps_[e.scheduled].action);
  }
  if (next_ - 1 == last_action_happening_ && !steps_.empty()) {
    last_action_state_ = state_;
    last_action_time_ = time_;
  }
  if (next_ < happenings_.size() && !running_.empty()) {
    try {
      if (auto v = check_invariants(state_, time_, happening_times_[next_])) return v;
      if (rates_.empty()) return std::nullopt;
      // Change is linear between happenings: the ends of the interval are
      // its extremes, so the state just before the next happening is the
      // other point an invariant must hold at.
      ExplicitState before_next = state_;
      advance(before_next, happening_times_[next_] - time_);
      return check_invariants(before_next, time_, happening_times_[next_]);
    } catch (const EvaluationError& error) {
      Violation v;
      v.kind = Violation::Kind::UndefinedValue;
      v.time = time_;
      v.condition = explain(error);
      return v;
    }
  }
  return std::nullopt;
}

ValidationResult HappeningExecutor::run(const std::vector<ScheduledStep>& steps, std::size_t plan_steps) {
  load(steps);
  return finish_run(plan_steps);
}

ValidationResult HappeningExecutor::run(const std::vector<ScheduledStep>& steps, std::size_t plan_steps,
                                        const ExecutionStart& start) {
  load(steps, start);
  return finish_run(plan_steps);
}

std::optional<Violation> HappeningExecutor::finish_trajectory(ValidationResult& result) {
  try {
    for (const GroundPreference& p : task_.pddl3.goal_preferences) {
      if (!holds(p.condition, state_, EvaluationContext{}, numeric_slack_)) trajectory_->count(p.preference);
    }
    // An empty plan has no happening: its initial state is its final state.
    if (auto v = trajectory_->finish(state_, time_)) return v;
  } catch (const EvaluationError& error) {
    return undefined_value(error, time_, "the PDDL 3 constraints or preferences");
  }
  const std::vector<std::string>& names = task_.lifted->pddl3.preferences;
  for (std::size_t p = 0; p < names.size(); ++p) result.preference_violations[names[p]] = trajectory_->violations()[p];
  return std::nullopt;
}

ValidationResult HappeningExecutor::finish_run(std::size_t plan_steps) {
  ValidationResult result;
  result.happenings = happenings_.size();
  while (!done()) {
    if (auto v = step()) {
      result.violation = std::move(v);
      return result;
    }
  }
  if (auto failed = first_unsatisfied(task_.goal, state_, EvaluationContext{}, numeric_slack_)) {
    Violation v;
    v.kind = Violation::Kind::GoalNotReached;
    v.time = time_;
    v.condition = describe(task_, task_.goal, *failed);
    result.violation = v;
    return result;
  }
  if (auto v = finish_trajectory(result)) {
    result.violation = std::move(v);
    return result;
  }
  // VAL's value: the metric after the last action happening; (total-time)
  // is its time, or the step count when the domain is not temporal.
  const double steps_and_literals = static_cast<double>(plan_steps + task_.timed_literals.size());
  result.makespan = last_action_time_;
  EvaluationContext context;
  context.violations = &trajectory_->violations();
  const bool timed = val_total_time_ ? task_.lifted->declares_time : task_.lifted->temporal;
  context.total_time = timed ? last_action_time_ : steps_and_literals;
  const ExplicitState& final_state = last_action_state_ ? *last_action_state_ : state_;
  result.total_cost = total_cost(task_, final_state);
  if (result.total_cost && std::isnan(*result.total_cost)) result.total_cost.reset();
  if (task_.metric) {
    try {
      result.metric = evaluate(task_.metric->expression, last_action_state_ ? *last_action_state_ : state_, context);
    } catch (const EvaluationError& error) {
      Violation v;
      v.kind = Violation::Kind::UndefinedValue;
      v.action = "the metric";
      v.condition = explain(error);
      result.violation = v;
      return result;
    }
    result.value = *result.metric;
  } else {
    result.value = steps_and_literals;
  }
  result.valid = true;
  return result;
}

}  // namespace alplan
