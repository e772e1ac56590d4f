// The paper's timeline (its Section 6.3): a plan becomes the chronologically
// ordered conditions that must hold in the observed world — each step's
// at-start condition at its start, its over-all condition on the open
// interval, its at-end condition at its end, and the goal after the last
// happening. The monitor checks observed states against it; a failed check
// is a Violation record, the same record the validator produces.
#pragma once

#include <optional>
#include <vector>

#include "planner/explicit_state.h"
#include "planner/violation.h"
#include "repair/executing_plan.h"

namespace alplan::repair {

struct TimelineEntry {
  enum class Kind : unsigned char { AtStart, OverAll, AtEnd, Goal };
  Kind kind = Kind::AtStart;
  double time = 0.0;
  double until = 0.0;  // OverAll: the end of the open interval
  std::size_t step = 0;  // index into the plan's steps (not for Goal)
  const ConditionSet* condition = nullptr;
};

class Timeline {
 public:
  explicit Timeline(const ExecutingPlan& plan);

  const std::vector<TimelineEntry>& entries() const { return entries_; }
  // Every time at which a step starts or ends, ascending.
  const std::vector<double>& happening_times() const { return happening_times_; }
  double end_time() const { return happening_times_.empty() ? 0.0 : happening_times_.back(); }

  // The conditions due at time t: at-start and at-end entries within
  // epsilon/10 of t, and over-all entries whose interval contains t.
  std::optional<Violation> check_due(double t, const ExplicitState& observed) const;
  // Looks ahead: a literal a later entry needs, false (or true, for a
  // negative one) now, that no step or timed literal scheduled before the
  // entry will change, means the plan will fail; better to know now.
  std::optional<Violation> check_ahead(double t, const ExplicitState& observed) const;
  std::optional<Violation> check_goal(double t, const ExplicitState& observed) const;

 private:
  std::optional<Violation> violated(const TimelineEntry& entry, double t, const ExplicitState& observed) const;
  // Whether some step or timed literal changes the fact in (after, before).
  bool changed_between(FactId fact, bool to, double after, double before) const;

  const ExecutingPlan* plan_;
  std::vector<TimelineEntry> entries_;
  std::vector<double> happening_times_;
  bool continuous_ = false;  // some step changes values continuously
};

}  // namespace alplan::repair
