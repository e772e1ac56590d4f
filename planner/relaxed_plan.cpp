// The relaxed plan of the temporal relaxed planning graph
// (temporal_rpg_exploration.h), extracted from an exploration.
#include <algorithm>
#include <cmath>

#include "planner/formula_evaluation.h"
#include "planner/numeric_effect_analysis.h"
#include "planner/temporal_rpg_exploration.h"

namespace alplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

void RelaxedPlan::resize(std::size_t actions) {
  counted_start_.resize(actions, 0);
  counted_end_.resize(actions, 0);
}

// Producers the relaxed plan so far falls short of (resource_shortfall.h):
// for each variable, the cheapest producer the exploration reaches (it goes
// on past the goals until one starts) joins the relaxed plan with its
// preconditions; the further applications it needs are `extra` steps.
std::vector<ActionId> RelaxedPlan::shortfall_producers(const SearchState& state, double& extra) {
  short_variables_.clear();
  ShortfallInput input;
  input.state = &state;
  input.plan = x_.plan_;
  for (ActionId a = 0; a < x_.rpg_.actions_.size(); ++a) {
    if (counted_start_.stamps[a] == x_.generation_ && counted_start_.values[a]) input.relaxed_starts.push_back(a);
  }
  input.min_duration = [this](ActionId a) { return x_.rpg_.actions_[a].durative ? x_.duration_of(a) : 0.0; };
  input.greatest = [&](NumericVarId v) {
    const double x = state.value(v);
    if (std::isnan(x)) return kInfinity;
    if (!std::isnan(x_.numeric_.greatest_now(v))) return x_.numeric_.greatest_now(v);
    return x_.plan_->changing_bounds(v, x, false, true).second;
  };
  std::vector<ActionId> seeds;
  for (const ResourceShortfall& s : x_.balance_->shortfalls(input)) {
    auto cheapest = [&]() -> ActionId {
      ActionId best = kNoId;
      for (ActionId w : s.producers) {
        if (!(x_.start_time_.at(w, x_.generation_) < kInfinity)) continue;
        if (best == kNoId || x_.start_cost_.at(w, x_.generation_) < x_.start_cost_.at(best, x_.generation_)) best = w;
      }
      return best;
    };
    ActionId producer = cheapest();
    while (producer == kNoId && !x_.queue_.empty()) {
      if (x_.process_next()) producer = cheapest();
    }
    if (producer == kNoId) continue;  // none reachable: the search must find out
    short_variables_.push_back(s.variable);
    // A producer the relaxed plan has already gave what it could.
    const bool counted = counted_start_.stamps[producer] == x_.generation_ && counted_start_.values[producer];
    if (!counted) seeds.push_back(producer);
    extra += (s.applications - (counted ? 0.0 : 1.0)) * (x_.rpg_.actions_[producer].durative ? 2.0 : 1.0);
  }
  return seeds;
}

// An unmet comparison's gap over the best constant step of a supporter of
// its variables: how many applications of that supporter it asks
// (numeric_effect_analysis.h). Each producer keeps the most any comparison asks.
void RelaxedPlan::note_repetitions(std::uint32_t comparison, const SearchState& state) {
  const std::optional<NumericDemand> demand = numeric_demand(*x_.rpg_.comparisons_[comparison], state);
  if (!demand) return;
  ActionId best = kNoId;
  double best_step = 0.0;
  for (NumericVarId v : demand->variables) {
    const ActionId a = x_.numeric_.supporter(v, demand->upward);
    if (a == kNoId) continue;
    const TemporalRpg::RelaxedAction& r = x_.rpg_.actions_[a];
    const std::optional<double> step =
        constant_step(r.start_numeric_effects, r.end_numeric_effects, v, demand->upward);
    if (step && *step > best_step) {
      best = a;
      best_step = *step;
    }
  }
  if (best == kNoId) return;
  const double times = std::ceil(demand->gap / best_step - 1e-9);
  if (times <= 1.0) return;
  for (auto& [a, most] : repetitions_) {
    if (a == best) {
      most = std::max(most, times);
      return;
    }
  }
  repetitions_.emplace_back(best, times);
}

// A running action whose over-all condition on changing values fails at
// its end unless something changes them first: a dead end when no action
// that changes them can start (in the relaxation) before that end, nor a
// running one end. The exploration goes on past the goal to see. (It takes
// the running action's end at its earliest; a plan that delayed the end
// to let help arrive is given up, as POPF gives up other orderings.)
// Where help can arrive and the resource balance counted none for those
// variables, the relaxed plan did not count it either (the interval
// relaxation sees no shortfall): one more step per such action. The helpers
// that can start now are helpful, so that hill-climbing tries them.
bool RelaxedPlan::continuous_dead_end(HeuristicValue& value) {
  const std::vector<std::pair<ActionId, std::vector<NumericVarId>>> failing = x_.plan_->invariants_failing_at_end();
  if (failing.empty()) return false;
  double horizon = 0.0;
  for (const auto& [action, variables] : failing) horizon = std::max(horizon, x_.plan_->pending_end_time(action));
  while (!x_.queue_.empty() && x_.queue_.top().time < horizon) x_.process_next();
  const ContinuousModel& model = *x_.continuous_;
  const GroundTask& task = x_.rpg_.index_.task();
  for (const auto& [action, variables] : failing) {
    const double end = x_.plan_->pending_end_time(action);
    bool helped = false;
    const std::optional<ContinuousStep> step = model.step(task.actions[action], SnapKind::Start, *x_.state_, std::nan(""));
    for (NumericVarId v : variables) {
      // A writer that moves v the way the invariant forbids is no help.
      const int needed = step ? bound_direction(step->invariants, v) : 0;
      for (ActionId w : model.writers(v)) {
        if (w == action) continue;
        if (needed != 0 && change_direction(model, task.actions[w], v, *x_.state_) == -needed) continue;
        const bool running = x_.state_->is_running(w);
        const double by = running ? x_.plan_->pending_end_time(w) : x_.start_time_.at(w, x_.generation_);
        if (by >= end) continue;
        helped = true;
        const std::vector<FactId>& pre = task.actions[w].at_start.positive;
        if (!running && x_.rpg_.options_.helpful_actions &&
            std::all_of(pre.begin(), pre.end(), [&](FactId f) { return x_.state_->fact(f); })) {
          value.helpful.push_back({task.actions[w].durative ? SnapKind::Start : SnapKind::Instant, w});
        }
      }
    }
    if (!helped) return true;
    // The balance counted the help this action needs already.
    const bool balanced = std::any_of(variables.begin(), variables.end(), [&](NumericVarId v) {
      return std::find(short_variables_.begin(), short_variables_.end(), v) != short_variables_.end();
    });
    if (!balanced) value.h += 1.0;
  }
  return false;
}

// Comparisons the state does not meet yet: the actions that first widened
// their variables join the relaxed plan, and a constant producer counts the
// repetitions the gap asks.
void RelaxedPlan::need_numeric(const std::vector<std::uint32_t>& comparisons) {
  for (std::uint32_t c : comparisons) {
    try {
      if (holds(*x_.rpg_.comparisons_[c], *state_, EvaluationContext{}, 0.0)) continue;  // true already
    } catch (const EvaluationError&) {
    }
    // The direction the comparison wants its variables to move, when it is
    // a sum of variables against a constant; else the first to widen them.
    const std::optional<NumericDemand> demand = numeric_demand(*x_.rpg_.comparisons_[c], *state_);
    for (NumericVarId v : x_.rpg_.comparison_variables_[c]) {
      const ActionId a = demand ? x_.numeric_.supporter(v, demand->upward) : x_.numeric_.first_supporter(v);
      if (a != kNoId) support_.push_back(a);
    }
    if (x_.rpg_.options_.count_repetitions && !x_.continuous_) note_repetitions(c, *state_);
  }
}

// A start commits the plan to its end, so it costs both.
void RelaxedPlan::count_start(ActionId a) {
  if (counted_start_.at(a, x_.generation_)) return;
  counted_start_.at(a, x_.generation_) = 1;
  count_ += 1.0;
  if (metric_) value_.cost += metric_->start_cost[a] + metric_->end_cost[a];
  const TemporalRpg::RelaxedAction& r = x_.rpg_.actions_[a];
  for (FactId f : r.start_pre) {
    // A windowed fact held over all comes from a provider whose span is
    // long enough for this action, not from the fact's earliest achiever
    // (a bake of 15 needs the 20-unit firing, not the 8-unit one).
    const ActionId provider = r.durative && x_.windows_.windowed(f) && !state_->fact(f)
                                  ? x_.windows_.span_provider(f, std::max(0.0, x_.duration_of(a)))
                                  : kNoId;
    if (provider != kNoId && provider != a) {
      support_.push_back(provider);
    } else {
      open_.push_back(f);
    }
  }
  need_numeric(r.start_numeric);
}

void RelaxedPlan::count_end(ActionId a) {
  if (counted_end_.at(a, x_.generation_)) return;
  counted_end_.at(a, x_.generation_) = 1;
  count_ += 1.0;
  const TemporalRpg::RelaxedAction& r = x_.rpg_.actions_[a];
  const bool running = state_->is_running(a);
  const std::vector<FactId>& invariant = x_.rpg_.index_.task().actions[a].over_all.positive;
  for (FactId f : r.end_pre) {
    // The start chose the provider of a windowed invariant.
    const bool chosen = !running && x_.windows_.windowed(f) && !state_->fact(f) &&
                        std::find(invariant.begin(), invariant.end(), f) != invariant.end();
    if (!chosen) open_.push_back(f);
  }
  need_numeric(r.end_numeric);
  if (!running) count_start(a);
}

void RelaxedPlan::count_action(ActionId a) {
  if (x_.rpg_.actions_[a].durative) {
    count_end(a);
  } else {
    count_start(a);
  }
}

// Supports every open fact by its achiever, and every numeric supporter.
void RelaxedPlan::drain() {
  const GroundTask& task = x_.rpg_.index_.task();
  while (!open_.empty() || !support_.empty()) {
    if (open_.empty()) {
      const ActionId a = support_.back();
      support_.pop_back();
      count_action(a);
      continue;
    }
    const FactId f = open_.back();
    open_.pop_back();
    if (x_.processed_.at(f, x_.generation_) == 2) continue;
    x_.processed_.at(f, x_.generation_) = 2;  // 2: supported in the relaxed plan
    const TemporalRpg::Achiever a = x_.achiever_.at(f, x_.generation_);
    switch (a.kind) {
      case TemporalRpg::AchieverKind::Start:
      case TemporalRpg::AchieverKind::Instant: count_start(a.index); break;
      case TemporalRpg::AchieverKind::End: count_end(a.index); break;
      case TemporalRpg::AchieverKind::Axiom: {
        const std::vector<FactId>& body = task.axioms[a.index].body.positive;
        open_.insert(open_.end(), body.begin(), body.end());
        break;
      }
      default: break;
    }
  }
}

HeuristicValue RelaxedPlan::extract(const SearchState& state, double goal_time) {
  state_ = &state;
  value_ = HeuristicValue{};
  value_.relaxed_makespan = goal_time;
  count_ = 0.0;
  metric_ = x_.rpg_.options_.metric.get();
  repetitions_.clear();
  open_.assign(x_.rpg_.goal_facts_.begin(), x_.rpg_.goal_facts_.end());
  support_.clear();
  need_numeric(x_.rpg_.goal_numeric_);
  drain();
  double extra = 0.0;
  short_variables_.clear();
  if (x_.balance_) {
    for (ActionId producer : shortfall_producers(state, extra)) count_action(producer);
    drain();
  }
  count_ += extra;
  // The further applications of constant producers the unmet comparisons ask.
  for (const auto& [a, times] : repetitions_) {
    count_ += (times - 1.0) * (x_.rpg_.actions_[a].durative ? 2.0 : 1.0);
    if (metric_) value_.cost += (times - 1.0) * (metric_->start_cost[a] + metric_->end_cost[a]);
  }
  // Every running action still owes its end.
  for (const RunningAction& r : state.running()) {
    if (!counted_end_.at(r.action, x_.generation_)) count_ += 1.0;
    if (metric_) value_.cost += metric_->end_cost[r.action];
  }
  value_.h = count_;
  if (x_.rpg_.options_.helpful_actions) add_helpful(state, value_);
  return std::move(value_);
}

// Helpful: relaxed-plan snaps whose preconditions hold now.
void RelaxedPlan::add_helpful(const SearchState& state, HeuristicValue& value) {
  const GroundTask& task = x_.rpg_.index_.task();
  auto holds_now = [&](const std::vector<FactId>& pre) {
    return std::all_of(pre.begin(), pre.end(), [&](FactId f) { return state.fact(f); });
  };
  for (ActionId a = 0; a < x_.rpg_.actions_.size(); ++a) {
    if (counted_end_.stamps[a] == x_.generation_ && counted_end_.values[a] && state.is_running(a) &&
        holds_now(x_.rpg_.actions_[a].end_pre)) {
      value.helpful.push_back({SnapKind::End, a});
    }
    if (counted_start_.stamps[a] == x_.generation_ && counted_start_.values[a] &&
        holds_now(task.actions[a].at_start.positive)) {
      value.helpful.push_back({x_.rpg_.actions_[a].durative ? SnapKind::Start : SnapKind::Instant, a});
    }
  }
}

}  // namespace alplan
