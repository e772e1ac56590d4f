#include "planner/resource_shortfall.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "planner/successor_generator.h"

namespace alplan {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A condition on one variable alone, as a bound: v >= threshold (lower) or
// v <= threshold (upper); an equality is both.
struct SingleBound {
  NumericVarId variable = kNoId;
  double threshold = 0.0;
  bool lower = false, upper = false;
};

std::optional<SingleBound> single_bound(const LinearCondition& c) {
  if (c.form.duration != 0.0 || c.form.terms.size() != 1 || c.form.terms[0].second == 0.0) return std::nullopt;
  const auto [v, k] = c.form.terms[0];
  SingleBound b;
  b.variable = v;
  b.threshold = -c.form.constant / k;  // constant + k v (op) 0
  const bool at_least = c.comparison == pddl::Comparison::GreaterEqual || c.comparison == pddl::Comparison::Greater;
  const bool at_most = c.comparison == pddl::Comparison::LessEqual || c.comparison == pddl::Comparison::Less;
  const bool equal = c.comparison == pddl::Comparison::Equal;
  b.lower = equal || (at_least && k > 0.0) || (at_most && k < 0.0);
  b.upper = equal || (at_least && k < 0.0) || (at_most && k > 0.0);
  return b;
}

double constant_change(const LinearAssignment& e) {
  if (!e.value.terms.empty() || e.value.duration != 0.0) return 0.0;
  if (e.assign == pddl::AssignOperator::Increase) return e.value.constant;
  if (e.assign == pddl::AssignOperator::Decrease) return -e.value.constant;
  return 0.0;
}

// The longest ?duration a duration constraint of the form
// constant + k v + d ?duration (op) 0 allows with v at `level`.
double duration_bound(const LinearCondition& c, NumericVarId v, double level) {
  const double d = c.form.duration;
  double rest = c.form.constant;
  for (const auto& [w, k] : c.form.terms) {
    if (w != v) return kInfinity;  // reads another changing value: unknown here, so no bound
    rest += k * level;
  }
  const bool at_most = c.comparison == pddl::Comparison::LessEqual || c.comparison == pddl::Comparison::Less;
  const bool at_least = c.comparison == pddl::Comparison::GreaterEqual || c.comparison == pddl::Comparison::Greater;
  const bool equal = c.comparison == pddl::Comparison::Equal;
  if ((d > 0.0 && (at_most || equal)) || (d < 0.0 && (at_least || equal))) return std::max(0.0, -rest / d);
  return kInfinity;
}

}  // namespace

int bound_direction(const std::vector<LinearCondition>& conditions, NumericVarId v) {
  bool lower = false, upper = false;
  for (const LinearCondition& c : conditions) {
    const bool reads = std::any_of(c.form.terms.begin(), c.form.terms.end(), [&](const auto& t) { return t.first == v; });
    if (!reads) continue;
    const std::optional<SingleBound> b = single_bound(c);
    if (!b) return 0;
    lower = lower || b->lower;
    upper = upper || b->upper;
  }
  if (lower == upper) return 0;
  return lower ? 1 : -1;
}

int change_direction(const ContinuousModel& model, const GroundAction& action, NumericVarId v,
                     const SearchState& state) {
  bool up = false, down = false;
  auto note = [&](double change) {
    up = up || change > 0.0;
    down = down || change < 0.0;
  };
  auto effects = [&](const ContinuousStep& step) {
    for (const LinearAssignment& e : step.effects) {
      if (e.variable != v) continue;
      const double change = constant_change(e);
      if (change == 0.0) return false;  // an assignment, or a change read from other values
      note(change);
    }
    return true;
  };
  const std::optional<ContinuousStep> start = model.step(action, SnapKind::Start, state, std::nan(""));
  if (!start || !effects(*start)) return 0;
  for (const auto& [w, r] : start->rates) {
    if (w == v) note(r);
  }
  if (action.durative) {
    const std::optional<ContinuousStep> end = model.step(action, SnapKind::End, state, std::nan(""));
    if (!end || !effects(*end)) return 0;
  }
  if (up == down) return 0;
  return up ? 1 : -1;
}

void ResourceBalance::ask(const std::vector<LinearCondition>& conditions, std::vector<Account>& accounts) const {
  for (const LinearCondition& c : conditions) {
    const std::optional<SingleBound> b = single_bound(c);
    if (!b || !b->lower) continue;
    Account& account = accounts[b->variable];
    account.need = std::max(account.need, b->threshold);
    account.asked = true;
  }
}

double ResourceBalance::production(ActionId producer, NumericVarId v, const ShortfallInput& input, double need) const {
  const GroundAction& g = task_.actions[producer];
  const std::optional<ContinuousStep> start = model_.step(g, SnapKind::Start, *input.state, std::nan(""));
  if (!start) return 0.0;
  double discrete = 0.0, rate = 0.0;
  for (const LinearAssignment& e : start->effects) {
    if (e.variable == v) discrete += std::max(0.0, constant_change(e));
  }
  if (g.durative) {
    if (const std::optional<ContinuousStep> end = model_.step(g, SnapKind::End, *input.state, std::nan(""))) {
      for (const LinearAssignment& e : end->effects) {
        if (e.variable == v) discrete += std::max(0.0, constant_change(e));
      }
    }
  }
  for (const auto& [w, r] : start->rates) {
    if (w == v) rate += r;
  }
  if (rate <= 0.0) return discrete;
  // The producer's own over-all upper bound on v caps what it can reach.
  double cap = kInfinity;
  for (const LinearCondition& c : start->invariants) {
    const std::optional<SingleBound> b = single_bound(c);
    if (b && b->variable == v && b->upper) cap = std::min(cap, b->threshold);
  }
  const DurationWindow window = duration_window(g, Moment::Start, *input.state, &model_);
  if (!window.valid) return discrete;
  double longest = window.max;
  for (const LinearCondition& c : start->conditions) {
    if (c.form.duration == 0.0) continue;
    // Optimistic: the producer starts at whichever level the plan can ask
    // of it that lets it run longest.
    double bound = duration_bound(c, v, need);
    if (std::isfinite(cap)) bound = std::max(bound, duration_bound(c, v, cap));
    longest = std::min(longest, bound);
  }
  double continuous = rate * longest;
  if (std::isfinite(cap)) continuous = std::min(continuous, std::max(0.0, cap - need));
  return discrete + continuous;
}

void ResourceBalance::add_changes(ActionId a, double duration, bool running, const ShortfallInput& input,
                                  std::vector<Account>& accounts) const {
  const GroundAction& g = task_.actions[a];
  const std::optional<ContinuousStep> start = model_.step(g, SnapKind::Start, *input.state, std::nan(""));
  if (!start) return;
  auto count = [&](NumericVarId v, double change) {
    if (change < 0.0) accounts[v].consumed -= change;
    else accounts[v].produced += change;
  };
  if (!running) {
    for (const LinearAssignment& e : start->effects) count(e.variable, constant_change(e));
  }
  if (g.durative) {
    if (const std::optional<ContinuousStep> end = model_.step(g, SnapKind::End, *input.state, std::nan(""))) {
      for (const LinearAssignment& e : end->effects) count(e.variable, constant_change(e));
    }
  }
  for (const auto& [v, r] : start->rates) {
    if (!accounts[v].asked) continue;
    if (r > 0.0) {
      accounts[v].produced += production(a, v, input, accounts[v].need);
    } else if (r < 0.0) {
      const double span =
          running ? std::max(0.0, input.plan->pending_end_time(a) - input.plan->changing_value_time(v)) : duration;
      accounts[v].consumed -= r * std::max(0.0, span);
    }
  }
}

std::vector<ResourceShortfall> ResourceBalance::shortfalls(const ShortfallInput& input) const {
  const SearchState& state = *input.state;
  std::vector<Account> accounts(task_.numeric.size());
  // First what the plan asks of each variable, then what it does to them:
  // what a producer gives depends on the least level asked.
  for (ActionId a : input.relaxed_starts) {
    const GroundAction& g = task_.actions[a];
    if (const std::optional<ContinuousStep> start = model_.step(g, SnapKind::Start, state, std::nan(""))) {
      ask(start->conditions, accounts);
      ask(start->invariants, accounts);
    }
    if (!g.durative) continue;
    if (const std::optional<ContinuousStep> end = model_.step(g, SnapKind::End, state, std::nan(""))) {
      ask(end->conditions, accounts);
    }
  }
  for (const RunningAction& r : state.running()) {
    if (const std::optional<ContinuousStep> start = model_.step(task_.actions[r.action], SnapKind::Start, state,
                                                                std::nan(""))) {
      ask(start->invariants, accounts);
    }
  }
  if (const std::optional<std::vector<LinearCondition>> goal = model_.goal(task_.goal, state)) ask(*goal, accounts);

  for (ActionId a : input.relaxed_starts) add_changes(a, std::max(0.0, input.min_duration(a)), false, input, accounts);
  for (const RunningAction& r : state.running()) add_changes(r.action, 0.0, true, input, accounts);

  std::vector<ResourceShortfall> out;
  for (NumericVarId v = 0; v < accounts.size(); ++v) {
    const Account& account = accounts[v];
    if (!account.asked || !model_.changing(v)) continue;
    const double missing = account.need + account.consumed - account.produced;
    if (!(missing - state.value(v) > 1e-6)) continue;
    const double level = input.greatest(v);
    if (!std::isfinite(level)) continue;
    const double amount = missing - level;
    if (!(amount > 1e-6)) continue;
    double best = 0.0;
    std::vector<ActionId> producers;
    for (ActionId w : model_.writers(v)) {
      if (state.is_running(w)) continue;
      const double given = production(w, v, input, account.need);
      if (!(given > 1e-9)) continue;
      best = std::max(best, given);
      producers.push_back(w);
    }
    if (best <= 0.0) continue;  // nothing produces it: the search, not the estimate, must find out
    const double applications = std::isfinite(best) ? std::min(std::ceil(amount / best - 1e-9), 1e6) : 1.0;
    out.push_back({v, amount, applications, std::move(producers)});
  }
  return out;
}

}  // namespace alplan
