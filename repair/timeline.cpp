#include "repair/timeline.h"

#include <algorithm>

#include "planner/formula_evaluation.h"

namespace alplan::repair {

Timeline::Timeline(const ExecutingPlan& plan) : plan_(&plan) {
  using K = TimelineEntry::Kind;
  const GroundTask& task = *plan.task;
  for (std::size_t s = 0; s < plan.steps.size(); ++s) {
    const ScheduledAction& step = plan.steps[s];
    const GroundAction& action = task.actions[step.action];
    continuous_ = continuous_ || !action.continuous.empty();
    entries_.push_back({K::AtStart, step.start, step.start, s, &action.at_start});
    happening_times_.push_back(step.start);
    if (!action.durative) continue;
    entries_.push_back({K::OverAll, step.start, step.end(), s, &action.over_all});
    entries_.push_back({K::AtEnd, step.end(), step.end(), s, &action.at_end});
    happening_times_.push_back(step.end());
  }
  std::sort(happening_times_.begin(), happening_times_.end());
  happening_times_.erase(std::unique(happening_times_.begin(), happening_times_.end()), happening_times_.end());
  const double last = happening_times_.empty() ? 0.0 : happening_times_.back();
  entries_.push_back({K::Goal, last, last, plan.steps.size(), &task.goal});
  std::stable_sort(entries_.begin(), entries_.end(),
                   [](const TimelineEntry& a, const TimelineEntry& b) { return a.time < b.time; });
}

std::optional<Violation> Timeline::violated(const TimelineEntry& entry, double t, const ExplicitState& observed) const {
  using K = TimelineEntry::Kind;
  if (entry.condition->empty()) return std::nullopt;
  EvaluationContext context;
  if (entry.kind != K::Goal) context.duration = plan_->steps[entry.step].duration;
  // Over all, values that change with time are compared with the slack the
  // validator gives them (a battery planned down to its reserve exactly).
  const double slack = entry.kind == K::OverAll && !continuous_ ? 0.0 : kNumericSlack;
  std::optional<Unsatisfied> failed;
  try {
    failed = first_unsatisfied(*entry.condition, observed, context, slack);
  } catch (const EvaluationError& error) {
    Violation v;
    v.kind = Violation::Kind::UndefinedValue;
    v.time = t;
    v.condition = error.what();
    return v;
  }
  if (!failed) return std::nullopt;
  Violation v;
  v.time = t;
  v.condition = describe(*plan_->task, *entry.condition, *failed);
  switch (entry.kind) {
    case K::Goal: v.kind = Violation::Kind::GoalNotReached; return v;
    case K::OverAll: v.kind = Violation::Kind::UnsatisfiedInvariant; v.until = entry.until; break;
    case K::AtStart: v.kind = Violation::Kind::UnsatisfiedPrecondition; break;
    case K::AtEnd: v.kind = Violation::Kind::UnsatisfiedPrecondition; break;
  }
  const ScheduledAction& step = plan_->steps[entry.step];
  const bool durative = plan_->task->actions[step.action].durative;
  v.action = step.name + (!durative ? "" : entry.kind == K::AtEnd ? " - end" : entry.kind == K::AtStart ? " - start" : "");
  v.step = entry.step;
  return v;
}

std::optional<Violation> Timeline::check_due(double t, const ExplicitState& observed) const {
  using K = TimelineEntry::Kind;
  const double tolerance = plan_->epsilon / 10.0;
  for (const TimelineEntry& e : entries_) {
    const bool point = (e.kind == K::AtStart || e.kind == K::AtEnd) && std::abs(e.time - t) <= tolerance;
    const bool during = e.kind == K::OverAll && e.time + tolerance < t && t < e.until - tolerance;
    if (!point && !during) continue;
    if (auto v = violated(e, t, observed)) return v;
  }
  return std::nullopt;
}

bool Timeline::changed_between(FactId fact, bool to, double after, double before) const {
  const GroundTask& task = *plan_->task;
  auto touches = [&](const HappeningEffects& effects) {
    const std::vector<FactId>& list = to ? effects.add : effects.del;
    if (std::find(list.begin(), list.end(), fact) != list.end()) return true;
    return std::any_of(effects.conditional.begin(), effects.conditional.end(), [&](const ConditionalEffect& c) {
      const std::vector<FactId>& l = to ? c.add : c.del;
      return std::find(l.begin(), l.end(), fact) != l.end();
    });
  };
  for (const ScheduledAction& s : plan_->steps) {
    const GroundAction& a = task.actions[s.action];
    if (s.start > after && s.start < before && touches(a.start)) return true;
    if (a.durative && s.end() > after && s.end() < before && touches(a.end)) return true;
  }
  for (const GroundTimedLiteral& til : task.timed_literals) {
    if (til.fact == fact && til.positive == to && til.time > after && til.time < before) return true;
  }
  return task.is_derived(fact);  // derived facts follow others; judged when due
}

std::optional<Violation> Timeline::check_ahead(double t, const ExplicitState& observed) const {
  const GroundTask& task = *plan_->task;
  const double tolerance = plan_->epsilon / 10.0;
  for (const TimelineEntry& e : entries_) {
    // An invariant whose interval opens now is looked at too: a robot that
    // sees the senior is not in the room does not begin a handover there.
    const bool opening = e.kind == TimelineEntry::Kind::OverAll && e.time > t - tolerance;
    if (e.time <= t + tolerance && !opening) continue;
    // The goal is judged after the last happening, so its effects count,
    // and so is an invariant, which holds from just after its step's start;
    // a step's condition is judged before simultaneous effects.
    const bool after_effects = e.kind == TimelineEntry::Kind::Goal || e.kind == TimelineEntry::Kind::OverAll;
    const double before = after_effects ? e.time + tolerance : e.time - tolerance;
    // Happenings due now are not yet dispatched when the monitor looks.
    const double after = t - tolerance;
    std::optional<std::string> doomed;
    for (FactId f : e.condition->positive) {
      if (!doomed && !observed.fact(f) && !changed_between(f, true, after, before)) doomed = task.fact_name(f);
    }
    for (FactId f : e.condition->negative) {
      if (!doomed && observed.fact(f) && !changed_between(f, false, after, before)) {
        doomed = "(not " + task.fact_name(f) + ")";
      }
    }
    if (!doomed) continue;
    Violation v;
    v.time = t;
    v.condition = *doomed;
    if (e.kind == TimelineEntry::Kind::Goal) {
      v.kind = Violation::Kind::GoalNotReached;
      return v;
    }
    const ScheduledAction& step = plan_->steps[e.step];
    const bool durative = task.actions[step.action].durative;
    using K = TimelineEntry::Kind;
    v.kind = e.kind == K::OverAll ? Violation::Kind::UnsatisfiedInvariant : Violation::Kind::UnsatisfiedPrecondition;
    v.until = e.until;
    v.action = step.name + (!durative ? "" : e.kind == K::AtEnd ? " - end" : e.kind == K::AtStart ? " - start" : "");
    v.step = e.step;
    return v;
  }
  return std::nullopt;
}

std::optional<Violation> Timeline::check_goal(double t, const ExplicitState& observed) const {
  for (const TimelineEntry& e : entries_) {
    if (e.kind == TimelineEntry::Kind::Goal) return violated(e, t, observed);
  }
  return std::nullopt;
}

}  // namespace alplan::repair
