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
    : task_(task),
      epsilon_(options.epsilon),
      val_total_time_(options.val_total_time),
      numeric_slack_(options.numeric_slack),
      report_all_(options.report_all) {}

bool HappeningExecutor::record(std::optional<Violation> v) {
  if (!v) return false;
  // An invariant failing at both ends of an interval is one violation.
  for (const Violation& seen : step_violations_) {
    if (seen.message() == v->message()) return false;
  }
  step_violations_.push_back(std::move(*v));
  return !report_all_;
}

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

bool HappeningExecutor::check_invariants(const ExplicitState& state, double at, double until) {
  bool failed_any = false;
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
      failed_any = true;
      if (record(std::move(v))) return true;
    }
  }
  return failed_any;
}

std::optional<Violation> HappeningExecutor::step() {
  step_violations_.clear();
  // VAL checks trajectory constraints in the state before each happening:
  // the initial state, then each happening's result but the last (finish_run).
  auto observe = [&]() -> std::optional<Violation> {
    try {
      return trajectory_->observe(state_, time_);
    } catch (const EvaluationError& error) {
      return undefined_value(error, time_, "the PDDL 3 constraints");
    }
  };
  std::optional<ExplicitState> before;
  if (observer_) before = state_;
  if (next_ == 0 && trajectory_->active() && record(observe())) return step_violations_.front();
  const std::size_t index = next_;
  execute_happening();
  const bool stopped = !report_all_ && !step_violations_.empty();
  if (!stopped && !done() && trajectory_->active()) record(observe());
  if (observer_) {
    HappeningRecord happening{index, happening_times_[index], {}, &*before, &state_, step_violations_};
    for (const Event& e : happenings_[index]) happening.members.push_back(event_name(e));
    observer_(happening);
  }
  if (step_violations_.empty()) return std::nullopt;
  return step_violations_.front();
}

void HappeningExecutor::execute_members(const std::vector<Event>& events) {
  // An undefined value stops the member (or the stage) it arose in: with
  // report_all the other members' conditions are still checked, but a
  // happening whose effects cannot all be evaluated changes nothing.
  auto undefined = [&](const EvaluationError& error, const Event& e) {
    Violation v = violation(Violation::Kind::UndefinedValue, e);
    v.condition = explain(error);
    return v;
  };
  for (const Event& e : events) {
    try {
      if (record(check_conditions(e))) return;
    } catch (const EvaluationError& error) {
      if (record(undefined(error, e))) return;
    }
  }
  const Event* current = &events.front();
  try {
    // With one member too: VAL refuses an action that assigns a value twice.
    if (record(check_mutex(events))) return;
    for (const Event& e : events) {
      current = &e;
      if (e.point == Point::Start) start_rates(e.scheduled, state_);
    }
    current = &events.front();
    record(apply(events));
  } catch (const EvaluationError& error) {
    record(undefined(error, *current));
  }
}

void HappeningExecutor::execute_happening() {
  const std::vector<Event>& events = happenings_[next_];
  advance(state_, happening_times_[next_] - time_);
  time_ = happening_times_[next_];
  ++next_;
  execute_members(events);
  if (!report_all_ && !step_violations_.empty()) return;
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
  if (next_ < happenings_.size() && !running_.empty()) check_running();
}

void HappeningExecutor::check_running() {
  try {
    if (check_invariants(state_, time_, happening_times_[next_]) && !report_all_) return;
    if (rates_.empty()) return;
    // Change is linear between happenings: the ends of the interval are
    // its extremes, so the state just before the next happening is the
    // other point an invariant must hold at.
    ExplicitState before_next = state_;
    advance(before_next, happening_times_[next_] - time_);
    check_invariants(before_next, time_, happening_times_[next_]);
  } catch (const EvaluationError& error) {
    Violation v;
    v.kind = Violation::Kind::UndefinedValue;
    v.time = time_;
    v.condition = explain(error);
    record(std::move(v));
  }
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

std::vector<Violation> HappeningExecutor::unmet_goals() const {
  using P = Unsatisfied::Part;
  const ConditionSet& goal = task_.goal;
  const EvaluationContext context{};
  std::vector<Unsatisfied> failed;
  if (!report_all_ || goal.never) {
    if (auto first = first_unsatisfied(goal, state_, context, numeric_slack_)) failed.push_back(*first);
  } else {
    for (std::size_t i = 0; i < goal.positive.size(); ++i) {
      if (!state_.fact(goal.positive[i])) failed.push_back({P::Positive, i});
    }
    for (std::size_t i = 0; i < goal.negative.size(); ++i) {
      if (state_.fact(goal.negative[i])) failed.push_back({P::Negative, i});
    }
    for (std::size_t i = 0; i < goal.numeric.size(); ++i) {
      if (!holds(goal.numeric[i], state_, context, numeric_slack_)) failed.push_back({P::Numeric, i});
    }
    for (std::size_t i = 0; i < goal.complex.size(); ++i) {
      if (!holds(goal.complex[i], state_, context, numeric_slack_)) failed.push_back({P::Complex, i});
    }
  }
  std::vector<Violation> violations;
  for (const Unsatisfied& where : failed) {
    Violation v;
    v.kind = Violation::Kind::GoalNotReached;
    v.time = time_;
    v.condition = describe(task_, goal, where);
    violations.push_back(std::move(v));
  }
  return violations;
}

ValidationResult HappeningExecutor::finish_run(std::size_t plan_steps) {
  ValidationResult result;
  result.happenings = happenings_.size();
  auto failed = [&result]() -> ValidationResult& {
    result.violation = result.violations.front();
    return result;
  };
  while (!done()) {
    step();
    result.violations.insert(result.violations.end(), step_violations_.begin(), step_violations_.end());
    if (!report_all_ && !result.violations.empty()) return failed();
  }
  for (Violation& v : unmet_goals()) result.violations.push_back(std::move(v));
  if (!report_all_ && !result.violations.empty()) return failed();
  if (auto v = finish_trajectory(result)) result.violations.push_back(std::move(*v));
  if (!result.violations.empty()) return failed();
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
      result.violations.push_back(v);
      return failed();
    }
    result.value = *result.metric;
  } else {
    result.value = steps_and_literals;
  }
  result.valid = true;
  return result;
}

}  // namespace alplan
