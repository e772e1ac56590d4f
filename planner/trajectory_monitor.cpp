#include "planner/trajectory_monitor.h"

#include "pddl_parser/writer.h"
#include "planner/formula_evaluation.h"

namespace alplan {

TrajectoryMonitor::TrajectoryMonitor(const GroundTask& task, double numeric_slack)
    : task_(task),
      numeric_slack_(numeric_slack),
      memory_(task.pddl3.constraints.size()),
      monitor_counted_(task.pddl3.monitors, false),
      violations_(task.lifted ? task.lifted->pddl3.preferences.size() : 0, 0.0) {}

bool TrajectoryMonitor::holds(const ConditionSet& c, const ExplicitState& state) const {
  return alplan::holds(c, state, EvaluationContext{}, numeric_slack_);
}

std::optional<Violation> TrajectoryMonitor::violated(std::size_t k, double time, const std::string& why) {
  const GroundConstraint& g = task_.pddl3.constraints[k];
  memory_[k].violated = true;
  if (g.preference) {
    if (!monitor_counted_[g.monitor]) {
      monitor_counted_[g.monitor] = true;
      count(*g.preference);
    }
    return std::nullopt;
  }
  Violation v;
  v.kind = Violation::Kind::ConstraintViolated;
  v.time = time;
  v.condition = g.text + ": " + why;
  return v;
}

std::optional<Violation> TrajectoryMonitor::observe(const ExplicitState& state, double time) {
  std::optional<Violation> first;
  // Every constraint sees every state, even after a violation, so that the
  // memories stay right for the preferences checked after it.
  for (std::size_t k = 0; k < memory_.size(); ++k) {
    std::optional<Violation> v = check(k, state, time);
    if (v && !first) first = std::move(v);
  }
  return first;
}

std::optional<Violation> TrajectoryMonitor::check(std::size_t k, const ExplicitState& state, double time) {
  const GroundConstraint& g = task_.pddl3.constraints[k];
  Memory& m = memory_[k];
  switch (g.op) {
    case ModalOperator::AtEnd: return std::nullopt;
    case ModalOperator::Always:
      if (!holds(g.requirement, state)) return violated(k, time, "false at time " + pddl::format_number(time));
      return std::nullopt;
    case ModalOperator::HoldAfter:
      if (time > g.deadline && !holds(g.requirement, state)) {
        return violated(k, time, "false at time " + pddl::format_number(time));
      }
      return std::nullopt;
    case ModalOperator::HoldDuring:
      if (g.from <= time && time < g.deadline && !holds(g.requirement, state)) {
        return violated(k, time, "false at time " + pddl::format_number(time));
      }
      return std::nullopt;
    case ModalOperator::Sometime:
      m.met = m.met || holds(g.requirement, state);
      return std::nullopt;
    case ModalOperator::Within:
      if (m.met) return std::nullopt;
      if (time > g.deadline) {
        m.met = true;  // reported once, as VAL drops the deadline
        return violated(k, time, "not reached by " + pddl::format_number(g.deadline));
      }
      m.met = holds(g.requirement, state);
      return std::nullopt;
    case ModalOperator::AlwaysWithin: {
      if (holds(g.trigger, state)) m.deadlines.push_back(time + g.deadline);
      if (m.deadlines.empty()) return std::nullopt;
      const bool now = holds(g.requirement, state);
      std::optional<Violation> v;
      std::vector<double> open;
      for (double d : m.deadlines) {
        if (time > d) {
          if (!v) v = violated(k, time, "not reached by " + pddl::format_number(d));
        } else if (!now) {
          open.push_back(d);
        }
      }
      m.deadlines = std::move(open);
      return v;
    }
    case ModalOperator::SometimeAfter:
      if (holds(g.trigger, state)) m.pending = true;
      if (m.pending && holds(g.requirement, state)) m.pending = false;
      return std::nullopt;
    case ModalOperator::AtMostOnce: {
      const bool now = holds(g.requirement, state);
      if (m.phase == Phase::NotYet && now) m.phase = Phase::Holding;
      if (m.phase == Phase::Holding && !now) m.phase = Phase::Released;
      if (m.phase == Phase::Released && now) return violated(k, time, "true again at time " + pddl::format_number(time));
      return std::nullopt;
    }
    case ModalOperator::SometimeBefore: {
      // The requirement must have held in an earlier state, not this one.
      const bool seen_before = m.requirement_seen;
      m.requirement_seen = m.requirement_seen || holds(g.requirement, state);
      if (!seen_before && holds(g.trigger, state)) {
        return violated(k, time, "the first condition holds at time " + pddl::format_number(time) +
                                     " without the second before it");
      }
      return std::nullopt;
    }
  }
  return std::nullopt;
}

std::optional<Violation> TrajectoryMonitor::check_final(std::size_t k, const ExplicitState& state) {
  const GroundConstraint& g = task_.pddl3.constraints[k];
  const Memory& m = memory_[k];
  switch (g.op) {
    case ModalOperator::AtEnd:
      if (!holds(g.requirement, state)) return violated(k, 0.0, "false in the final state");
      return std::nullopt;
    case ModalOperator::Sometime:
    case ModalOperator::Within:
      if (!m.met) return violated(k, 0.0, "never true");
      return std::nullopt;
    case ModalOperator::SometimeAfter:
      if (m.pending) return violated(k, 0.0, "the second condition never holds after the first");
      return std::nullopt;
    case ModalOperator::AlwaysWithin:
      if (!m.deadlines.empty()) {
        return violated(k, 0.0, "not reached by " + pddl::format_number(m.deadlines.front()) + " before the plan ends");
      }
      return std::nullopt;
    default: return std::nullopt;
  }
}

std::optional<Violation> TrajectoryMonitor::finish(const ExplicitState& state, double time) {
  std::optional<Violation> first = observe(state, time);
  for (std::size_t k = 0; k < memory_.size(); ++k) {
    std::optional<Violation> v = check_final(k, state);
    if (v && !first) {
      v->time = time;
      first = std::move(v);
    }
  }
  return first;
}

}  // namespace alplan
