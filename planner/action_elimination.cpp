#include "planner/action_elimination.h"

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

// The first kept step, in the plan's order, whose propositional conditions
// fail once the removed steps are gone; nullopt when none does.
std::optional<std::uint32_t> first_unsupported(const GroundTask& task, const SearchState& start,
                                               const Solution& solution, const std::vector<bool>& removed) {
  std::vector<bool> facts(task.facts.size());
  for (FactId f = 0; f < facts.size(); ++f) facts[f] = start.fact(f);
  auto apply = [&](const HappeningEffects& e) {
    for (FactId f : e.del) facts[f] = false;
    for (FactId f : e.add) facts[f] = true;
  };
  for (std::uint32_t i = 0; i < solution.steps.size(); ++i) {
    if (removed[i]) continue;
    const StepRecord& r = solution.steps[i];
    if (r.snap.kind == SnapKind::TimedLiteral) {
      const GroundTimedLiteral& til = task.timed_literals[r.snap.index];
      facts[til.fact] = til.positive;
      continue;
    }
    const GroundAction& a = task.actions[r.snap.index];
    const bool end = r.snap.kind == SnapKind::End;
    // An end also needs its invariant still to hold (it is checked up to it).
    if (!holds(task, end ? a.at_end : a.at_start, facts) || (end && !holds(task, a.over_all, facts))) return i;
    apply(end ? a.end : a.start);
  }
  return std::nullopt;
}

// Whether the propositional goal still holds after the kept steps: a
// removal that loses it would only be refused by the judge, at the price
// of a rescheduling and two validations.
bool goal_kept(const GroundTask& task, const SearchState& start, const Solution& solution,
               const std::vector<bool>& removed) {
  std::vector<bool> facts(task.facts.size());
  for (FactId f = 0; f < facts.size(); ++f) facts[f] = start.fact(f);
  for (std::uint32_t i = 0; i < solution.steps.size(); ++i) {
    if (removed[i]) continue;
    const StepRecord& r = solution.steps[i];
    if (r.snap.kind == SnapKind::TimedLiteral) {
      facts[task.timed_literals[r.snap.index].fact] = task.timed_literals[r.snap.index].positive;
      continue;
    }
    const HappeningEffects& e = r.snap.kind == SnapKind::End ? task.actions[r.snap.index].end
                                                              : task.actions[r.snap.index].start;
    for (FactId f : e.del) facts[f] = false;
    for (FactId f : e.add) facts[f] = true;
  }
  return holds(task, task.goal, facts);
}

}  // namespace

std::optional<std::vector<bool>> removal_set(const GroundTask& task, const SearchState& start,
                                             const Solution& solution, std::uint32_t action_step) {
  const std::uint32_t n = static_cast<std::uint32_t>(solution.steps.size());
  if (action_step >= n || !removable(solution.steps[action_step])) return std::nullopt;
  std::vector<bool> removed(n, false);
  mark_action(solution, action_step, removed);
  // Each round drops the first step left without support, until none is.
  for (std::uint32_t round = 0; round < n; ++round) {
    const std::optional<std::uint32_t> failing = first_unsupported(task, start, solution, removed);
    if (!failing) return goal_kept(task, start, solution, removed) ? std::optional(removed) : std::nullopt;
    if (!removable(solution.steps[*failing])) return std::nullopt;
    mark_action(solution, *failing, removed);
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
