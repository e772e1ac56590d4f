// The exploration of the temporal relaxed planning graph
// (temporal_rpg_exploration.h), and the few TemporalRpg members that run it:
// in this file, not temporal_rpg.cpp, so that temporal_rpg.h's module does
// not include the exploration, which includes it (no include loop).
#include "planner/temporal_rpg_exploration.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <queue>

#include "planner/formula_evaluation.h"
#include "planner/successor_generator.h"
#include "planner/temporal_rpg.h"

namespace alplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

TemporalRpg::Exploration::Exploration(TemporalRpg& rpg)
    : rpg_(rpg),
      continuous_(rpg.index_.continuous().get()),
      numeric_(rpg.index_.task().numeric.size()),
      windows_(rpg.index_.task()),
      relaxed_plan_(*this) {
  if (continuous_ && rpg.options_.resource_balance) balance_.emplace(rpg.index_.task(), *continuous_);
}

TemporalRpg::TemporalRpg(const TaskIndex& index, TemporalRpgOptions options, std::shared_ptr<const Graph> like)
    : index_(index),
      options_(options),
      graph_(like && fits(*like, index.task()) ? std::move(like) : build(index)),
      actions_(graph_->actions),
      comparisons_(graph_->comparisons),
      start_watchers_(graph_->start_watchers),
      sound_start_watchers_(graph_->sound_start_watchers),
      end_watchers_(graph_->end_watchers),
      axiom_watchers_(graph_->axiom_watchers),
      numeric_watchers_(graph_->numeric_watchers),
      amount_readers_(graph_->amount_readers),
      comparison_variables_(graph_->comparison_variables),
      goal_facts_(graph_->goal_facts),
      goal_numeric_(graph_->goal_numeric) {
  const GroundTask& task = index_.task();
  const std::size_t facts = task.facts.size(), actions = task.actions.size();
  exploration_ = std::make_unique<Exploration>(*this);
  Exploration& x = *exploration_;
  x.fact_time_.resize(facts, kInfinity);
  x.fact_cost_.resize(facts, kInfinity);
  x.start_cost_.resize(actions, 0.0);
  x.achiever_.resize(facts, Achiever{});
  x.processed_.resize(facts, 0);
  x.end_ready_.resize(actions, 0.0);
  x.enabled_time_.resize(actions, 0.0);
  x.start_count_.resize(actions, 0);
  x.end_count_.resize(actions, 0);
  x.parked_start_.resize(actions, 0);
  x.parked_end_.resize(actions, 0);
  x.relaxed_plan_.resize(actions);
  x.running_.resize(actions, 0);
  x.axiom_count_.resize(task.axioms.size(), 0);
  x.parked_on_.resize(facts);
  x.started_at_.resize(actions, 0.0);
  x.start_time_.resize(actions, kInfinity);
  x.ended_.resize(actions, 0);
}

TemporalRpg::~TemporalRpg() = default;

void TemporalRpg::Exploration::reach(FactId f, double time, Achiever achiever, double cost) {
  const bool by_action = achiever.kind != AchieverKind::State && achiever.kind != AchieverKind::TimedLiteral;
  bool opened = false;
  if (by_action && windows_.windowed(f)) {
    // Only providers' starts give a windowed fact: usable for their span at
    // most (VAL lets a holder start with its provider and end with it).
    const double span = windows_.provider_span(achiever.index);
    opened = achiever.kind == AchieverKind::Start && windows_.open_span(f, time, span, achiever.index);
  } else if (by_action) {
    opened = windows_.open_from(f, time);
  }
  if (opened) {
    // Actions that waited for this fact to become usable again retry.
    std::vector<std::pair<ActionId, bool>> waiting = std::move(parked_on_[f]);
    parked_on_[f].clear();
    for (const auto& [a, end] : waiting) {
      if (end) {
        try_end(a);
      } else {
        try_start(a, std::max(time, enabled_time_.at(a, generation_)));
      }
    }
  }
  double& current = fact_time_.at(f, generation_);
  double& current_cost = fact_cost_.at(f, generation_);
  if (time > current + 1e-9) return;
  // A fact that holds now stays the state's: an action may reach it earlier
  // (it need not be ordered after the fact's writer in the partial plan),
  // which the time keeps, but the relaxed plan needs no action for it. Else
  // a state where the goal holds, reached by a precondition-free action,
  // had h = 1, was never tested as a goal, and the search claimed no plan.
  const bool held = achiever_.at(f, generation_).kind == AchieverKind::State;
  if (time > current - 1e-9) {
    // As early: keep the cheaper achiever (h_add), so that what is already
    // there (a lit match) beats what would have to be started.
    if (cost < current_cost && !held) {
      current_cost = cost;
      achiever_.at(f, generation_) = achiever;
    }
    return;
  }
  current = time;
  if (!held) {
    current_cost = cost;
    achiever_.at(f, generation_) = achiever;
  }
  queue_.push({time, f});
}





void TemporalRpg::Exploration::apply_numeric(const std::vector<const NumericAssignment*>& effects, ActionId source) {
  std::vector<NumericVarId> changed;
  for (const NumericAssignment* a : effects) {
    if (numeric_.apply(*a, source)) changed.push_back(a->variable);
  }
  while (!changed.empty()) {
    const NumericVarId v = changed.back();
    changed.pop_back();
    // Effects whose amounts read the variable apply again with the wider
    // amount: (increase (x) (y)) reached before y grew adds more now. The
    // bounds only widen, and widen to infinity after a few rounds
    // (numeric_intervals.h), so this ends.
    for (const auto& [reader, end] : rpg_.amount_readers_[v]) {
      const bool applied = end ? ended_.at(reader, generation_) != 0 : start_time_.at(reader, generation_) < kInfinity;
      if (!applied) continue;
      const RelaxedAction& r = rpg_.actions_[reader];
      for (const NumericAssignment* n : end ? r.end_numeric_effects : r.start_numeric_effects) {
        if (numeric_.apply(*n, reader)) changed.push_back(n->variable);
      }
      if (end && running_.at(reader, generation_)) {
        for (const NumericAssignment* n : r.end_returns) {
          if (numeric_.apply(*n, reader)) changed.push_back(n->variable);
        }
      }
    }
    // Actions waiting for a comparison on this variable try again.
    for (ActionId waiting : rpg_.numeric_watchers_[v]) {
      if (parked_start_.at(waiting, generation_)) {
        parked_start_.at(waiting, generation_) = 0;
        try_start(waiting, enabled_time_.at(waiting, generation_));
      }
      if (parked_end_.at(waiting, generation_)) {
        parked_end_.at(waiting, generation_) = 0;
        try_end(waiting);
      }
    }
  }
}

bool TemporalRpg::Exploration::satisfiable(const std::vector<std::uint32_t>& comparisons) const {
  for (std::uint32_t c : comparisons) {
    if (!numeric_.satisfiable(*rpg_.comparisons_[c])) return false;
  }
  return true;
}

HeuristicValue TemporalRpg::evaluate(const SearchState& state, const PartialPlan& plan, Relaxation mode) {
  return exploration_->run(state, plan, mode);
}

std::vector<FactId> TemporalRpg::unreached_goals() const {
  const Exploration& x = *exploration_;
  std::vector<FactId> unreached;
  for (FactId f : goal_facts_) {
    const bool reached = x.fact_time_.stamps[f] == x.generation_ && x.fact_time_.values[f] < kInfinity;
    if (!reached) unreached.push_back(f);
  }
  return unreached;
}

// A lower bound on the action's duration in any state from here on: the
// relaxed times must be lower bounds for a dead end to be one.
double TemporalRpg::Exploration::duration_of(ActionId a) {
  const double fixed = rpg_.actions_[a].fixed_duration;
  return std::isnan(fixed) ? 0.0 : fixed;
}

double TemporalRpg::Exploration::cost_of(const std::vector<FactId>& facts) {
  double sum = 0.0;
  for (FactId f : facts) sum += fact_cost_.at(f, generation_);
  return std::min(sum, 1e9);
}

void TemporalRpg::Exploration::park(FactId fact, ActionId a, bool end) {
  std::vector<std::pair<ActionId, bool>>& waiting = parked_on_[fact];
  if (waiting.empty()) parked_facts_.push_back(fact);
  // Once per fact: an action parked on several facts and woken by one parks
  // on the others again.
  if (std::find(waiting.begin(), waiting.end(), std::pair{a, end}) == waiting.end()) waiting.emplace_back(a, end);
}

// A fit that fails may fail on several facts, and any of them opening anew
// (an action achieving it again) can make it fit: the action waits on every
// restricted fact it needs, not only the one the fit stopped at.
void TemporalRpg::Exploration::park_on_windows(ActionId a, bool end,
                                               std::initializer_list<const std::vector<FactId>*> lists) {
  for (const std::vector<FactId>* list : lists) {
    for (FactId f : *list) {
      if (windows_.restricted(f)) park(f, a, end);
    }
  }
}

void TemporalRpg::Exploration::try_start(ActionId a, double time) {
  const RelaxedAction& r = rpg_.actions_[a];
  const GroundAction& g = rpg_.index_.task().actions[a];
  enabled_time_.at(a, generation_) = time;
  const bool sound = mode_ == Relaxation::Sound;
  if (!satisfiable(sound ? r.sound_start_numeric : r.start_numeric)) {
    parked_start_.at(a, generation_) = 1;
    return;
  }
  const double epsilon = gap();
  const double duration = r.durative ? duration_of(a) : 0.0;
  if (duration < 0.0) return;
  // The sound relaxation fits only the start's own condition: what the
  // invariant and the end need is the end's to wait for.
  static const std::vector<FactId> kNone;
  const std::vector<FactId>& over_all = sound ? kNone : r.held_over_all;
  const std::vector<FactId>& at_end = sound ? kNone : r.held_at_end;
  const FactWindows::Fit fit = windows_.fit(time, duration, g.at_start.positive, over_all, at_end);
  if (!fit.ok) {
    park_on_windows(a, false, {&g.at_start.positive, &over_all, &at_end});
    return;
  }
  const double start = fit.start;
  start_time_.at(a, generation_) = start;
  const double cost = 1.0 + cost_of(r.start_pre);
  if (!r.durative) {
    for (FactId f : r.start_add) reach(f, start + epsilon, {AchieverKind::Instant, a}, cost);
    apply_numeric(r.start_numeric_effects, a);
    return;
  }
  for (FactId f : r.start_add) reach(f, start + epsilon, {AchieverKind::Start, a}, cost);
  apply_numeric(r.start_numeric_effects, a);
  // A running action started again: its end is already owed by the run in
  // the state, which comes no later than the new run's would.
  if (running_.at(a, generation_)) return;
  started_at_.at(a, generation_) = start;
  start_cost_.at(a, generation_) = cost;
  double& ready = end_ready_.at(a, generation_);
  ready = std::max(ready, start + duration);
  if (--end_count_.at(a, generation_) == 0) try_end(a);
}

void TemporalRpg::Exploration::try_end(ActionId a) {
  const RelaxedAction& r = rpg_.actions_[a];
  if (!satisfiable(mode_ == Relaxation::Sound ? r.sound_end_numeric : r.end_numeric)) {
    parked_end_.at(a, generation_) = 1;
    return;
  }
  const GroundAction& g = rpg_.index_.task().actions[a];
  double end = end_ready_.at(a, generation_);
  // A running action's end: its invariant was checked as it ran.
  const bool running = running_.at(a, generation_);
  if (!running) {
    // An end waiting for its at-end condition need not keep the action
    // running from its earliest start: the action may start late, so its
    // invariant need only fit the shortest run ending then (or later).
    const double start = started_at_.at(a, generation_);
    const double shortest = duration_of(a);
    static const std::vector<FactId> kNoFacts;
    const FactWindows::Fit fit =
        windows_.fit(std::max(start, end - shortest), shortest, kNoFacts, r.held_over_all, r.held_at_end);
    if (!fit.ok) {
      park_on_windows(a, true, {&r.held_over_all, &r.held_at_end});
      return;
    }
    end = std::max(end, fit.start + shortest);
  } else {
    const FactWindows::Fit fit = windows_.fit(end, 0.0, g.at_end.positive, {}, {});
    if (!fit.ok) {
      park_on_windows(a, true, {&g.at_end.positive});
      return;
    }
  }
  const double cost = (running ? 1.0 : start_cost_.at(a, generation_) + 1.0) + cost_of(r.end_pre);
  for (FactId f : r.end_add) reach(f, end + gap(), {AchieverKind::End, a}, cost);
  ended_.at(a, generation_) = 1;
  apply_numeric(r.end_numeric_effects, a);
  if (running) apply_numeric(r.end_returns, a);
}

bool TemporalRpg::Exploration::process_next() {
  const Event e = queue_.top();
  queue_.pop();
  // Stale (the fact was reached earlier since) or seen already.
  if (e.time > fact_time_.at(e.fact, generation_) || processed_.at(e.fact, generation_)) return false;
  processed_.at(e.fact, generation_) = 1;
  process(e.fact, e.time);
  return true;
}

void TemporalRpg::Exploration::process(FactId f, double time) {
  for (ActionId a : (mode_ == Relaxation::Sound ? rpg_.sound_start_watchers_ : rpg_.start_watchers_)[f]) {
    if (--start_count_.at(a, generation_) == 0) try_start(a, time);
  }
  for (ActionId a : rpg_.end_watchers_[f]) {
    double& ready = end_ready_.at(a, generation_);
    ready = std::max(ready, time);
    if (--end_count_.at(a, generation_) == 0) try_end(a);
  }
  for (std::uint32_t x : rpg_.axiom_watchers_[f]) {
    if (--axiom_count_.at(x, generation_) == 0) {
      reach(rpg_.index_.task().axioms[x].head, time, {AchieverKind::Axiom, x},
            cost_of(rpg_.index_.task().axioms[x].body.positive));
    }
  }
  if (std::binary_search(rpg_.goal_facts_.begin(), rpg_.goal_facts_.end(), f)) --goals_left_;
}

// A new generation: every action waits for its preconditions (an end also
// for its start), every axiom for its body; the numbers, the windows and
// the parked actions start from the state.
void TemporalRpg::Exploration::start_counters(const SearchState& state, const PartialPlan& plan) {
  const GroundTask& task = rpg_.index_.task();
  if (++generation_ == 0) generation_ = 1;  // stamps start at 0: never reuse it
  queue_ = {};
  goals_left_ = rpg_.goal_facts_.size();
  start_count_.fallback = 0;
  for (ActionId a = 0; a < rpg_.actions_.size(); ++a) {
    const RelaxedAction& r = rpg_.actions_[a];
    start_count_.values[a] = static_cast<std::uint32_t>((mode_ == Relaxation::Sound ? r.sound_start_pre : r.start_pre).size());
    start_count_.stamps[a] = generation_;
    end_count_.values[a] = static_cast<std::uint32_t>(rpg_.actions_[a].end_pre.size()) + 1;
    end_count_.stamps[a] = generation_;
  }
  for (std::uint32_t x = 0; x < task.axioms.size(); ++x) {
    axiom_count_.values[x] = static_cast<std::uint32_t>(task.axioms[x].body.positive.size());
    axiom_count_.stamps[x] = generation_;
  }
  numeric_.reset(state, plan, continuous_);
  for (FactId f : parked_facts_) parked_on_[f].clear();
  parked_facts_.clear();
  windows_.reset(state, plan, mode_ == Relaxation::Guiding, gap());
}

// What holds now, what timed literals will give, what running actions owe,
// and the actions that need nothing.
void TemporalRpg::Exploration::seed(const SearchState& state, const PartialPlan& plan) {
  const GroundTask& task = rpg_.index_.task();
  for (std::size_t word = 0; word < state.bits().size(); ++word) {
    for (std::uint64_t w = state.bits()[word]; w != 0; w &= w - 1) {
      const FactId f = static_cast<FactId>(word * 64 + static_cast<std::size_t>(__builtin_ctzll(w)));
      reach(f, plan.available_from(f, gap()), {AchieverKind::State, 0}, 0.0);
    }
  }
  for (std::uint32_t t = state.next_timed_literal(); t < task.timed_literals.size(); ++t) {
    const GroundTimedLiteral& til = task.timed_literals[t];
    if (til.positive) reach(til.fact, til.time + gap(), {AchieverKind::TimedLiteral, t}, 0.0);
  }
  for (const RunningAction& running : state.running()) {
    if (running_.at(running.action, generation_)) continue;  // the earliest run of it counts
    running_.at(running.action, generation_) = 1;
    double& ready = end_ready_.at(running.action, generation_);
    ready = std::max(ready, plan.pending_end_time(running.action));
    --end_count_.at(running.action, generation_);
  }
  // Actions that need nothing start now. A running one may start again:
  // at once in the sound relaxation (VAL lets an action overlap itself),
  // once its run ends in the guiding one (POPF's search starts no second
  // run, and a provider started again at once would open spans a holder
  // cannot use: temporal-machine-shop's firings).
  for (ActionId a = 0; a < rpg_.actions_.size(); ++a) {
    const RelaxedAction& r = rpg_.actions_[a];
    if (!(mode_ == Relaxation::Sound ? r.sound_start_pre : r.start_pre).empty()) continue;
    const bool running = running_.at(a, generation_);
    try_start(a, running && mode_ == Relaxation::Guiding ? plan.pending_end_time(a) : 0.0);
  }
  for (const RunningAction& running : state.running()) {
    if (end_count_.at(running.action, generation_) == 0) try_end(running.action);
  }
  for (std::uint32_t x = 0; x < task.axioms.size(); ++x) {
    if (task.axioms[x].body.positive.empty()) reach(task.axioms[x].head, 0.0, {AchieverKind::Axiom, x}, 0.0);
  }
}

HeuristicValue TemporalRpg::Exploration::run(const SearchState& state, const PartialPlan& plan, Relaxation mode) {
  state_ = &state;
  plan_ = &plan;
  mode_ = mode;
  start_counters(state, plan);
  seed(state, plan);
  double goal_time = 0.0;
  bool reached = goals_reached();
  while (!queue_.empty() && !reached) {
    const double time = queue_.top().time;
    if (!process_next()) continue;
    goal_time = time;
    reached = goals_reached();
  }
  if (!reached) return HeuristicValue{};
  HeuristicValue value = relaxed_plan_.extract(state, goal_time);
  if (continuous_ && mode == Relaxation::Guiding && relaxed_plan_.continuous_dead_end(value)) return HeuristicValue{};
  return value;
}











}  // namespace alplan
