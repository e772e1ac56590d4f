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

// Which sides a comparison (form op 0) bounds the form from: an equality both.
struct Sides {
  bool at_least = false, at_most = false;
};

Sides sides(pddl::Comparison c) {
  const bool equal = c == pddl::Comparison::Equal;
  return {equal || c == pddl::Comparison::GreaterEqual || c == pddl::Comparison::Greater,
          equal || c == pddl::Comparison::LessEqual || c == pddl::Comparison::Less};
}

std::optional<SingleBound> single_bound(const LinearCondition& c) {
  if (c.form.duration != 0.0 || c.form.terms.size() != 1 || c.form.terms[0].second == 0.0) return std::nullopt;
  const auto [v, k] = c.form.terms[0];
  SingleBound b;
  b.variable = v;
  b.threshold = -c.form.constant / k;  // constant + k v (op) 0
  const Sides side = sides(c.comparison);
  b.lower = (side.at_least && k > 0.0) || (side.at_most && k < 0.0);
  b.upper = (side.at_least && k < 0.0) || (side.at_most && k > 0.0);
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
  const Sides side = sides(c.comparison);
  if ((d > 0.0 && side.at_most) || (d < 0.0 && side.at_least)) return std::max(0.0, -rest / d);
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

ResourceBalance::Snaps ResourceBalance::snaps_of(ActionId a, bool running, const SearchState& state) const {
  const GroundAction& g = task_.actions[a];
  Snaps out{a, running, model_.step(g, SnapKind::Start, state, std::nan("")), std::nullopt};
  if (g.durative) out.end = model_.step(g, SnapKind::End, state, std::nan(""));
  return out;
}

void ResourceBalance::ask(const Snaps& snaps, std::vector<Account>& accounts) {
  auto ask_all = [&](const std::vector<LinearCondition>& conditions) {
    for (const LinearCondition& c : conditions) {
      const std::optional<SingleBound> b = single_bound(c);
      if (!b || !b->lower) continue;
      Account& account = accounts[b->variable];
      account.need = std::max(account.need, b->threshold);
      account.asked = true;
    }
  };
  // A running action asks only its invariant any more.
  if (snaps.start) ask_all(snaps.start->invariants);
  if (snaps.running) return;
  if (snaps.start) ask_all(snaps.start->conditions);
  if (snaps.end) ask_all(snaps.end->conditions);
}

double ResourceBalance::discrete_gain(const Snaps& snaps, NumericVarId v) {
  double gain = 0.0;
  for (const std::optional<ContinuousStep>* step : {&snaps.start, &snaps.end}) {
    if (!*step) continue;
    for (const LinearAssignment& e : (*step)->effects) {
      if (e.variable == v) gain += std::max(0.0, constant_change(e));
    }
  }
  return gain;
}

double ResourceBalance::continuous_gain(const Snaps& snaps, NumericVarId v, const SearchState& state,
                                        double need) const {
  if (!snaps.start) return 0.0;
  const ContinuousStep& start = *snaps.start;
  double rate = 0.0;
  for (const auto& [w, r] : start.rates) {
    if (w == v) rate += r;
  }
  if (rate <= 0.0) return 0.0;
  // The producer's own over-all upper bound on v caps what it can reach.
  double cap = kInfinity;
  for (const LinearCondition& c : start.invariants) {
    const std::optional<SingleBound> b = single_bound(c);
    if (b && b->variable == v && b->upper) cap = std::min(cap, b->threshold);
  }
  const DurationWindow window = duration_window(task_.actions[snaps.action], Moment::Start, state, &model_);
  if (!window.valid) return 0.0;
  double longest = window.max;
  for (const LinearCondition& c : start.conditions) {
    if (c.form.duration == 0.0) continue;
    // Optimistic: the producer starts at whichever level the plan can ask
    // of it that lets it run longest.
    double bound = duration_bound(c, v, need);
    if (std::isfinite(cap)) bound = std::max(bound, duration_bound(c, v, cap));
    longest = std::min(longest, bound);
  }
  const double gain = rate * longest;
  return std::isfinite(cap) ? std::min(gain, std::max(0.0, cap - need)) : gain;
}

void ResourceBalance::add_changes(const Snaps& snaps, double duration, const ShortfallInput& input,
                                  std::vector<Account>& accounts) const {
  if (!snaps.start) return;
  auto count = [&](NumericVarId v, double change) {
    if (change < 0.0) accounts[v].consumed -= change;
    else accounts[v].produced += change;
  };
  // A running action's start effects are in the state already.
  if (!snaps.running) {
    for (const LinearAssignment& e : snaps.start->effects) count(e.variable, constant_change(e));
  }
  if (snaps.end) {
    for (const LinearAssignment& e : snaps.end->effects) count(e.variable, constant_change(e));
  }
  for (const auto& [v, r] : snaps.start->rates) {
    if (!accounts[v].asked) continue;
    if (r > 0.0) {
      accounts[v].produced += continuous_gain(snaps, v, *input.state, accounts[v].need);
    } else if (r < 0.0) {
      const double span = snaps.running ? input.plan->pending_end_time(snaps.action) - input.plan->changing_value_time(v)
                                        : duration;
      accounts[v].consumed -= r * std::max(0.0, span);
    }
  }
}

std::vector<ResourceShortfall> ResourceBalance::shortfalls(const ShortfallInput& input) const {
  const SearchState& state = *input.state;
  std::vector<Snaps> involved;
  for (ActionId a : input.relaxed_starts) involved.push_back(snaps_of(a, false, state));
  for (const RunningAction& r : state.running()) involved.push_back(snaps_of(r.action, true, state));
  std::vector<Account> accounts(task_.numeric.size());
  // First what the plan asks of each variable, then what it does to them:
  // what a producer gives depends on the least level asked.
  for (const Snaps& snaps : involved) ask(snaps, accounts);
  if (const std::optional<std::vector<LinearCondition>> goal = model_.goal(task_.goal, state)) {
    ask(Snaps{kNoId, false, ContinuousStep{*goal, {}, {}, {}}, std::nullopt}, accounts);
  }
  for (const Snaps& snaps : involved) {
    const double duration = snaps.running ? 0.0 : std::max(0.0, input.min_duration(snaps.action));
    add_changes(snaps, duration, input, accounts);
  }

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
      const Snaps snaps = snaps_of(w, false, state);
      const double given = discrete_gain(snaps, v) + continuous_gain(snaps, v, state, account.need);
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
