#include "planner/action_elimination.h"

#include <optional>
#include <vector>

namespace alplan {
namespace {

// A step and, for a durative action, its other snap.
void mark_action(const Solution& solution, std::uint32_t step, std::vector<bool>& removed) {
  const StepRecord& r = solution.steps[step];
  removed[step] = true;
  if (r.snap.kind == SnapKind::End && r.start_step != kNoId) removed[r.start_step] = true;
  if (r.snap.kind == SnapKind::Start) {
    for (std::uint32_t j = step + 1; j < solution.steps.size(); ++j) {
      if (solution.steps[j].snap.kind == SnapKind::End && solution.steps[j].start_step == step) removed[j] = true;
    }
  }
}

bool removable(const StepRecord& r) {
  return r.snap.kind != SnapKind::TimedLiteral && !(r.snap.kind == SnapKind::End && r.start_step == kNoId);
}

// Whether the propositional part of a condition holds (derived facts are
// left to the validator).
bool holds(const GroundTask& task, const ConditionSet& c, const std::vector<bool>& facts) {
  for (FactId f : c.positive) {
    if (!task.is_derived(f) && !facts[f]) return false;
  }
  for (FactId f : c.negative) {
    if (!task.is_derived(f) && facts[f]) return false;
  }
  return true;
}

// The kept steps replayed in the plan's order on their propositional
// conditions and effects: the first whose condition fails, or the facts at
// the end.
struct Replay {
  std::optional<std::uint32_t> failing;
  std::vector<bool> facts;
};

Replay replay(const GroundTask& task, const SearchState& start, const Solution& solution,
              const std::vector<bool>& removed) {
  Replay r{std::nullopt, std::vector<bool>(task.facts.size())};
  for (FactId f = 0; f < r.facts.size(); ++f) r.facts[f] = start.fact(f);
  for (std::uint32_t i = 0; i < solution.steps.size(); ++i) {
    if (removed[i]) continue;
    const StepRecord& step = solution.steps[i];
    if (step.snap.kind == SnapKind::TimedLiteral) {
      const GroundTimedLiteral& til = task.timed_literals[step.snap.index];
      r.facts[til.fact] = til.positive;
      continue;
    }
    const GroundAction& a = task.actions[step.snap.index];
    const bool end = step.snap.kind == SnapKind::End;
    // An end also needs its invariant still to hold (it is checked up to it).
    if (!holds(task, end ? a.at_end : a.at_start, r.facts) || (end && !holds(task, a.over_all, r.facts))) {
      r.failing = i;
      return r;
    }
    const HappeningEffects& e = end ? a.end : a.start;
    for (FactId f : e.del) r.facts[f] = false;
    for (FactId f : e.add) r.facts[f] = true;
  }
  return r;
}

}  // namespace

std::optional<std::vector<bool>> removal_set(const GroundTask& task, const SearchState& start,
                                             const Solution& solution, std::uint32_t action_step) {
  const std::uint32_t n = static_cast<std::uint32_t>(solution.steps.size());
  if (action_step >= n || !removable(solution.steps[action_step])) return std::nullopt;
  std::vector<bool> removed(n, false);
  mark_action(solution, action_step, removed);
  // Each round drops the first step left without support, until none is;
  // a removal that loses the propositional goal would only be refused by
  // the judge, at the price of a rescheduling and two validations.
  for (std::uint32_t round = 0; round < n; ++round) {
    const Replay r = replay(task, start, solution, removed);
    if (!r.failing) return holds(task, task.goal, r.facts) ? std::optional(removed) : std::nullopt;
    if (!removable(solution.steps[*r.failing])) return std::nullopt;
    mark_action(solution, *r.failing, removed);
  }
  return removed;
}

Solution without_steps(const Solution& solution, const std::vector<bool>& removed) {
  const std::uint32_t n = static_cast<std::uint32_t>(solution.steps.size());
  std::vector<std::uint32_t> renumbered(n, kNoId);
  Solution result = solution;
  result.steps.clear();
  result.times.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    if (removed[i]) continue;
    renumbered[i] = static_cast<std::uint32_t>(result.steps.size());
    StepRecord r = solution.steps[i];
    if (r.start_step != kNoId) r.start_step = renumbered[r.start_step];
    if (r.simultaneous_with != kNoId) r.simultaneous_with = renumbered[r.simultaneous_with];
    result.steps.push_back(r);
    if (i < solution.times.size()) result.times.push_back(solution.times[i]);
  }
  return result;
}

std::optional<Solution> eliminate_actions(const DeorderingInput& input, const Solution& solution,
                                          const std::function<bool(const Solution&)>& accept,
                                          const EliminationOptions& options) {
  const GroundTask& task = input.index.task();
  std::optional<Solution> best;
  std::size_t candidates = 0;
  bool removed_one = true;
  while (removed_one) {
    removed_one = false;
    const Solution& current = best ? *best : solution;
    // From the end: what is left after a removal is tried again from the
    // new plan's end.
    for (std::uint32_t i = static_cast<std::uint32_t>(current.steps.size()); i-- > 0;) {
      if (current.steps[i].snap.kind == SnapKind::Start) continue;  // an action by its end or instant
      if (passed(options.deadline) || candidates >= options.max_candidates) return best;
      const std::optional<std::vector<bool>> removed = removal_set(task, input.start, current, i);
      if (!removed) continue;
      ++candidates;
      std::optional<Solution> rescheduled = deorder(input, without_steps(current, *removed));
      if (!rescheduled || !accept(*rescheduled)) continue;
      best = std::move(*rescheduled);
      removed_one = true;
      break;  // `current` is gone
    }
  }
  return best;
}

}  // namespace alplan
