#include "planner/temporal_rpg.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <queue>

#include "planner/evaluation.h"
#include "planner/fact_windows.h"
#include "planner/numeric_relaxation.h"
#include "planner/resource_shortfall.h"
#include "planner/successor_generator.h"

namespace alplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Interval {
  double lo = -kInfinity;
  double hi = kInfinity;
};

Interval operator+(Interval a, Interval b) { return {a.lo + b.lo, a.hi + b.hi}; }
Interval operator-(Interval a, Interval b) { return {a.lo - b.hi, a.hi - b.lo}; }
Interval operator*(Interval a, Interval b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  Interval r{kInfinity, -kInfinity};
  for (double x : p) {
    if (std::isnan(x)) return {};  // 0 * inf: anything
    r.lo = std::min(r.lo, x);
    r.hi = std::max(r.hi, x);
  }
  return r;
}
Interval operator/(Interval a, Interval b) {
  if (b.lo <= 0.0 && b.hi >= 0.0) return {};
  return a * Interval{1.0 / b.hi, 1.0 / b.lo};
}

}  // namespace

// The per-evaluation work of the heuristic: times, counters and bounds, all
// stamped with the evaluation's generation so nothing is cleared between
// evaluations (the arrays are as long as the task has actions and facts).
class TemporalRpg::Exploration {
 public:
  explicit Exploration(TemporalRpg& rpg)
      : rpg_(rpg), continuous_(rpg.index_.continuous().get()), windows_(rpg.index_.task()) {
    if (continuous_ && rpg.options_.resource_balance) balance_.emplace(rpg.index_.task(), *continuous_);
  }
  HeuristicValue run(const SearchState& state, const PartialPlan& plan, Relaxation mode);

 private:
  template <typename T>
  struct Stamped {
    std::vector<T> values;
    std::vector<std::uint32_t> stamps;
    T fallback{};
    void resize(std::size_t n, T initial) {
      values.assign(n, initial);
      stamps.assign(n, 0);
      fallback = initial;
    }
    T& at(std::size_t i, std::uint32_t generation) {
      if (stamps[i] != generation) {
        stamps[i] = generation;
        values[i] = fallback;
      }
      return values[i];
    }
  };
  friend class TemporalRpg;

  void reach(FactId f, double time, Achiever achiever, double cost);
  double cost_of(const std::vector<FactId>& facts);
  void process(FactId f, double time);
  // Takes the earliest event off the queue and processes it; false when it
  // was stale.
  bool process_next();
  void try_start(ActionId a, double time);
  void try_end(ActionId a);
  void apply_numeric(const std::vector<const NumericAssignment*>& effects, ActionId source);
  bool satisfiable(const std::vector<std::uint32_t>& comparisons) const;
  Interval interval(const GroundExpression& e) const;
  void park(FactId fact, ActionId a, bool end);
  double duration_of(ActionId a);
  HeuristicValue extract(const SearchState& state, double goal_time);
  void add_helpful(const SearchState& state, HeuristicValue& value);
  bool continuous_dead_end(HeuristicValue& value);
  void note_repetitions(std::uint32_t comparison, const SearchState& state);
  std::vector<ActionId> shortfall_producers(const SearchState& state, double& extra);
  bool goals_reached() const { return goals_left_ == 0 && satisfiable(rpg_.goal_numeric_); }

  TemporalRpg& rpg_;
  Relaxation mode_ = Relaxation::Guiding;
  const ContinuousModel* continuous_;  // null without continuous change: read once, not per action
  std::vector<std::pair<ActionId, double>> repetitions_;  // producer, applications asked (extract's)
  const SearchState* state_ = nullptr;
  const PartialPlan* plan_ = nullptr;
  std::uint32_t generation_ = 0;
  Stamped<double> fact_time_, fact_cost_, end_ready_, enabled_time_, started_at_, start_cost_;
  Stamped<double> start_time_;  // infinite until started in this evaluation
  Stamped<Achiever> achiever_;
  Stamped<std::uint32_t> start_count_, end_count_, axiom_count_;
  Stamped<char> processed_, parked_start_, parked_end_, counted_start_, counted_end_;
  // The state's running actions, as a lookup: SearchState::is_running scans
  // its list, and try_end asks for every end the exploration reaches.
  Stamped<char> running_;
  std::vector<Interval> bounds_;
  // A changing variable's greatest value now where the bounds asked the
  // schedule for it, NaN elsewhere.
  std::vector<double> greatest_now_;
  std::optional<ResourceBalance> balance_;
  std::vector<NumericVarId> short_variables_;  // the last evaluation's, whose producers it counted
  std::vector<ActionId> supporter_;  // first action that widened each variable
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> queue_;
  std::size_t goals_left_ = 0;
  FactWindows windows_;
  // Actions waiting for a fact whose windows do not fit them to be achieved
  // again by an action (then it is usable for good).
  std::vector<std::vector<std::pair<ActionId, bool>>> parked_on_;
  std::vector<FactId> parked_facts_;
};

TemporalRpg::TemporalRpg(const TaskIndex& index, TemporalRpgOptions options, std::shared_ptr<const Graph> like)
    : index_(index),
      options_(options),
      graph_(like && fits(*like, index.task()) ? std::move(like) : build(index)),
      actions_(graph_->actions),
      comparisons_(graph_->comparisons),
      start_watchers_(graph_->start_watchers),
      end_watchers_(graph_->end_watchers),
      axiom_watchers_(graph_->axiom_watchers),
      numeric_watchers_(graph_->numeric_watchers),
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
  x.counted_start_.resize(actions, 0);
  x.counted_end_.resize(actions, 0);
  x.running_.resize(actions, 0);
  x.axiom_count_.resize(task.axioms.size(), 0);
  x.bounds_.resize(task.numeric.size());
  x.greatest_now_.resize(task.numeric.size());
  x.supporter_.resize(task.numeric.size(), kNoId);
  x.parked_on_.resize(facts);
  x.started_at_.resize(actions, 0.0);
  x.start_time_.resize(actions, kInfinity);
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

Interval TemporalRpg::Exploration::interval(const GroundExpression& e) const {
  using K = GroundExpression::Kind;
  switch (e.kind) {
    case K::Constant: return {e.value, e.value};
    case K::Variable: return bounds_[e.variable];
    case K::Add: {
      Interval r = interval(e.operands[0]);
      for (std::size_t i = 1; i < e.operands.size(); ++i) r = r + interval(e.operands[i]);
      return r;
    }
    case K::Multiply: {
      Interval r = interval(e.operands[0]);
      for (std::size_t i = 1; i < e.operands.size(); ++i) r = r * interval(e.operands[i]);
      return r;
    }
    case K::Subtract: return interval(e.operands[0]) - interval(e.operands[1]);
    case K::Divide: return interval(e.operands[0]) / interval(e.operands[1]);
    case K::Negate: {
      const Interval i = interval(e.operands[0]);
      return {-i.hi, -i.lo};
    }
    case K::Duration: return {0.0, kInfinity};
    default: return {};
  }
}

bool TemporalRpg::Exploration::satisfiable(const std::vector<std::uint32_t>& comparisons) const {
  for (std::uint32_t c : comparisons) {
    const GroundComparison& cmp = *rpg_.comparisons_[c];
    const Interval left = interval(cmp.left), right = interval(cmp.right);
    if (left.lo > left.hi || right.lo > right.hi) return false;  // an undefined variable
    const Interval d = left - right;
    bool ok = true;
    switch (cmp.comparison) {
      case pddl::Comparison::Less: ok = d.lo < 0.0; break;
      case pddl::Comparison::LessEqual: ok = d.lo <= 0.0; break;
      case pddl::Comparison::Equal: ok = d.lo <= 0.0 && d.hi >= 0.0; break;
      case pddl::Comparison::GreaterEqual: ok = d.hi >= 0.0; break;
      case pddl::Comparison::Greater: ok = d.hi > 0.0; break;
    }
    if (!ok) return false;
  }
  return true;
}

void TemporalRpg::Exploration::apply_numeric(const std::vector<const NumericAssignment*>& effects, ActionId source) {
  for (const NumericAssignment* a : effects) {
    Interval& b = bounds_[a->variable];
    const Interval before = b;
    const Interval v = interval(a->value);
    if (v.lo > v.hi) continue;  // reads an undefined variable
    switch (a->assign) {
      case pddl::AssignOperator::Assign:
        b = b.lo > b.hi ? v : Interval{std::min(b.lo, v.lo), std::max(b.hi, v.hi)};
        break;
      case pddl::AssignOperator::Increase:
      case pddl::AssignOperator::Decrease: {
        if (b.lo > b.hi) b = {0.0, 0.0};  // VAL starts an undefined value at 0
        const bool up = a->assign == pddl::AssignOperator::Increase;
        if ((up ? v.hi : -v.lo) > 0) b.hi = kInfinity;
        if ((up ? v.lo : -v.hi) < 0) b.lo = -kInfinity;
        break;
      }
      default: b = {}; break;
    }
    if (b.lo == before.lo && b.hi == before.hi) continue;
    if (supporter_[a->variable] == kNoId) supporter_[a->variable] = source;
    for (ActionId waiting : rpg_.numeric_watchers_[a->variable]) {
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
  if (parked_on_[fact].empty()) parked_facts_.push_back(fact);
  parked_on_[fact].emplace_back(a, end);
}

void TemporalRpg::Exploration::try_start(ActionId a, double time) {
  const RelaxedAction& r = rpg_.actions_[a];
  const GroundAction& g = rpg_.index_.task().actions[a];
  enabled_time_.at(a, generation_) = time;
  if (!satisfiable(r.start_numeric)) {
    parked_start_.at(a, generation_) = 1;
    return;
  }
  const double epsilon = plan_->epsilon();
  const double duration = r.durative ? duration_of(a) : 0.0;
  if (duration < 0.0) return;
  const FactWindows::Fit fit = windows_.fit(time, duration, g.at_start.positive, r.held_over_all, r.held_at_end);
  if (!fit.ok) {
    park(fit.blocking, a, false);
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
  if (!satisfiable(r.end_numeric)) {
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
    static const std::vector<FactId> kNone;
    const FactWindows::Fit fit =
        windows_.fit(std::max(start, end - shortest), shortest, kNone, r.held_over_all, r.held_at_end);
    if (!fit.ok) {
      park(fit.blocking, a, true);
      return;
    }
    end = std::max(end, fit.start + shortest);
  } else {
    const FactWindows::Fit fit = windows_.fit(end, 0.0, g.at_end.positive, {}, {});
    if (!fit.ok) {
      park(fit.blocking, a, true);
      return;
    }
  }
  const double cost = (running ? 1.0 : start_cost_.at(a, generation_) + 1.0) + cost_of(r.end_pre);
  for (FactId f : r.end_add) reach(f, end + plan_->epsilon(), {AchieverKind::End, a}, cost);
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
  for (ActionId a : rpg_.start_watchers_[f]) {
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

HeuristicValue TemporalRpg::Exploration::run(const SearchState& state, const PartialPlan& plan, Relaxation mode) {
  const GroundTask& task = rpg_.index_.task();
  state_ = &state;
  plan_ = &plan;
  mode_ = mode;
  if (++generation_ == 0) generation_ = 1;  // stamps start at 0: never reuse it
  queue_ = {};
  goals_left_ = rpg_.goal_facts_.size();
  // Counters: an action waits for its preconditions; an end also for its start.
  start_count_.fallback = 0;
  for (ActionId a = 0; a < rpg_.actions_.size(); ++a) {
    start_count_.values[a] = static_cast<std::uint32_t>(rpg_.actions_[a].start_pre.size());
    start_count_.stamps[a] = generation_;
    end_count_.values[a] = static_cast<std::uint32_t>(rpg_.actions_[a].end_pre.size()) + 1;
    end_count_.stamps[a] = generation_;
  }
  for (std::uint32_t x = 0; x < task.axioms.size(); ++x) {
    axiom_count_.values[x] = static_cast<std::uint32_t>(task.axioms[x].body.positive.size());
    axiom_count_.stamps[x] = generation_;
  }
  for (NumericVarId v = 0; v < bounds_.size(); ++v) {
    const double x = state.value(v);
    bounds_[v] = std::isnan(x) ? Interval{kInfinity, -kInfinity} : Interval{x, x};
    greatest_now_[v] = std::nan("");
    if (continuous_ && continuous_->changing(v) && !std::isnan(x)) {
      const ContinuousModel::NeededBounds needed = continuous_->needed_bounds(v, state);
      if (needed.least || needed.greatest) {
        const auto [lo, hi] = plan.changing_bounds(v, x, needed.least, needed.greatest);
        if (lo <= hi) bounds_[v] = Interval{lo, hi};
        if (lo <= hi && needed.greatest) greatest_now_[v] = hi;
      }
    }
    supporter_[v] = kNoId;
  }
  for (FactId f : parked_facts_) parked_on_[f].clear();
  parked_facts_.clear();
  windows_.reset(state, plan, mode == Relaxation::Guiding);
  // What holds now, what timed literals will give, what running actions owe.
  for (std::size_t word = 0; word < state.bits().size(); ++word) {
    for (std::uint64_t w = state.bits()[word]; w != 0; w &= w - 1) {
      const FactId f = static_cast<FactId>(word * 64 + static_cast<std::size_t>(__builtin_ctzll(w)));
      reach(f, plan.available_from(f), {AchieverKind::State, 0}, 0.0);
    }
  }
  for (std::uint32_t t = state.next_timed_literal(); t < task.timed_literals.size(); ++t) {
    const GroundTimedLiteral& til = task.timed_literals[t];
    if (til.positive) reach(til.fact, til.time + plan.epsilon(), {AchieverKind::TimedLiteral, t}, 0.0);
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
    if (!rpg_.actions_[a].start_pre.empty()) continue;
    const bool running = running_.at(a, generation_);
    try_start(a, running && mode_ == Relaxation::Guiding ? plan.pending_end_time(a) : 0.0);
  }
  for (const RunningAction& running : state.running()) {
    if (end_count_.at(running.action, generation_) == 0) try_end(running.action);
  }
  for (std::uint32_t x = 0; x < task.axioms.size(); ++x) {
    if (task.axioms[x].body.positive.empty()) reach(task.axioms[x].head, 0.0, {AchieverKind::Axiom, x}, 0.0);
  }
  double goal_time = 0.0;
  bool reached = goals_reached();
  while (!queue_.empty() && !reached) {
    const double time = queue_.top().time;
    if (!process_next()) continue;
    goal_time = time;
    reached = goals_reached();
  }
  if (!reached) return HeuristicValue{};
  HeuristicValue value = extract(state, goal_time);
  if (continuous_ && mode == Relaxation::Guiding && continuous_dead_end(value)) return HeuristicValue{};
  return value;
}

// Producers the relaxed plan so far falls short of (resource_shortfall.h):
// for each variable, the cheapest producer the exploration reaches (it goes
// on past the goals until one starts) joins the relaxed plan with its
// preconditions; the further applications it needs are `extra` steps.
std::vector<ActionId> TemporalRpg::Exploration::shortfall_producers(const SearchState& state, double& extra) {
  short_variables_.clear();
  ShortfallInput input;
  input.state = &state;
  input.plan = plan_;
  for (ActionId a = 0; a < rpg_.actions_.size(); ++a) {
    if (counted_start_.stamps[a] == generation_ && counted_start_.values[a]) input.relaxed_starts.push_back(a);
  }
  input.min_duration = [this](ActionId a) { return rpg_.actions_[a].durative ? duration_of(a) : 0.0; };
  input.greatest = [&](NumericVarId v) {
    const double x = state.value(v);
    if (std::isnan(x)) return kInfinity;
    if (!std::isnan(greatest_now_[v])) return greatest_now_[v];
    return plan_->changing_bounds(v, x, false, true).second;
  };
  std::vector<ActionId> seeds;
  for (const ResourceShortfall& s : balance_->shortfalls(input)) {
    auto cheapest = [&]() -> ActionId {
      ActionId best = kNoId;
      for (ActionId w : s.producers) {
        if (!(start_time_.at(w, generation_) < kInfinity)) continue;
        if (best == kNoId || start_cost_.at(w, generation_) < start_cost_.at(best, generation_)) best = w;
      }
      return best;
    };
    ActionId producer = cheapest();
    while (producer == kNoId && !queue_.empty()) {
      if (process_next()) producer = cheapest();
    }
    if (producer == kNoId) continue;  // none reachable: the search must find out
    short_variables_.push_back(s.variable);
    // A producer the relaxed plan has already gave what it could.
    const bool counted = counted_start_.stamps[producer] == generation_ && counted_start_.values[producer];
    if (!counted) seeds.push_back(producer);
    extra += (s.applications - (counted ? 0.0 : 1.0)) * (rpg_.actions_[producer].durative ? 2.0 : 1.0);
  }
  return seeds;
}

// An unmet comparison's gap over the best constant step of a supporter of
// its variables: how many applications of that supporter it asks
// (numeric_relaxation.h). Each producer keeps the most any comparison asks.
void TemporalRpg::Exploration::note_repetitions(std::uint32_t comparison, const SearchState& state) {
  const std::optional<NumericDemand> demand = numeric_demand(*rpg_.comparisons_[comparison], state);
  if (!demand) return;
  ActionId best = kNoId;
  double best_step = 0.0;
  for (NumericVarId v : demand->variables) {
    const ActionId a = supporter_[v];
    if (a == kNoId) continue;
    const RelaxedAction& r = rpg_.actions_[a];
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
bool TemporalRpg::Exploration::continuous_dead_end(HeuristicValue& value) {
  const std::vector<std::pair<ActionId, std::vector<NumericVarId>>> failing = plan_->invariants_failing_at_end();
  if (failing.empty()) return false;
  double horizon = 0.0;
  for (const auto& [action, variables] : failing) horizon = std::max(horizon, plan_->pending_end_time(action));
  while (!queue_.empty() && queue_.top().time < horizon) process_next();
  const ContinuousModel& model = *continuous_;
  const GroundTask& task = rpg_.index_.task();
  for (const auto& [action, variables] : failing) {
    const double end = plan_->pending_end_time(action);
    bool helped = false;
    const std::optional<ContinuousStep> step = model.step(task.actions[action], SnapKind::Start, *state_, std::nan(""));
    for (NumericVarId v : variables) {
      // A writer that moves v the way the invariant forbids is no help.
      const int needed = step ? bound_direction(step->invariants, v) : 0;
      for (ActionId w : model.writers(v)) {
        if (w == action) continue;
        if (needed != 0 && change_direction(model, task.actions[w], v, *state_) == -needed) continue;
        const bool running = state_->is_running(w);
        const double by = running ? plan_->pending_end_time(w) : start_time_.at(w, generation_);
        if (by >= end) continue;
        helped = true;
        const std::vector<FactId>& pre = task.actions[w].at_start.positive;
        if (!running && rpg_.options_.helpful_actions &&
            std::all_of(pre.begin(), pre.end(), [&](FactId f) { return state_->fact(f); })) {
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

HeuristicValue TemporalRpg::Exploration::extract(const SearchState& state, double goal_time) {
  const GroundTask& task = rpg_.index_.task();
  HeuristicValue value;
  value.relaxed_makespan = goal_time;
  double count = 0.0;
  repetitions_.clear();
  std::vector<FactId> open(rpg_.goal_facts_.begin(), rpg_.goal_facts_.end());
  std::vector<ActionId> numeric_support;
  auto need_numeric = [&](const std::vector<std::uint32_t>& comparisons) {
    for (std::uint32_t c : comparisons) {
      try {
        if (holds(*rpg_.comparisons_[c], state, EvaluationContext{}, 0.0)) continue;  // true already
      } catch (const EvaluationError&) {
      }
      for (NumericVarId v : rpg_.comparison_variables_[c]) {
        if (supporter_[v] != kNoId) numeric_support.push_back(supporter_[v]);
      }
      if (rpg_.options_.count_repetitions && !continuous_) note_repetitions(c, state);
    }
  };
  need_numeric(rpg_.goal_numeric_);
  const LinearMetric* metric = rpg_.options_.metric.get();
  // A start commits the plan to its end, so it costs both.
  auto count_start = [&](ActionId a) {
    if (counted_start_.at(a, generation_)) return;
    counted_start_.at(a, generation_) = 1;
    count += 1.0;
    if (metric) value.cost += metric->start_cost[a] + metric->end_cost[a];
    const RelaxedAction& r = rpg_.actions_[a];
    for (FactId f : r.start_pre) {
      // A windowed fact held over all comes from a provider whose span is
      // long enough for this action, not from the fact's earliest achiever
      // (a bake of 15 needs the 20-unit firing, not the 8-unit one).
      const ActionId provider = r.durative && windows_.windowed(f) && !state.fact(f)
                                    ? windows_.span_provider(f, std::max(0.0, duration_of(a)))
                                    : kNoId;
      if (provider != kNoId && provider != a) {
        numeric_support.push_back(provider);
      } else {
        open.push_back(f);
      }
    }
    need_numeric(r.start_numeric);
  };
  auto count_end = [&](ActionId a) {
    if (counted_end_.at(a, generation_)) return;
    counted_end_.at(a, generation_) = 1;
    count += 1.0;
    const RelaxedAction& r = rpg_.actions_[a];
    const bool running = state.is_running(a);
    const std::vector<FactId>& invariant = task.actions[a].over_all.positive;
    for (FactId f : r.end_pre) {
      // The start chose the provider of a windowed invariant.
      const bool chosen = !running && windows_.windowed(f) && !state.fact(f) &&
                          std::find(invariant.begin(), invariant.end(), f) != invariant.end();
      if (!chosen) open.push_back(f);
    }
    need_numeric(r.end_numeric);
    if (!running) count_start(a);
  };
  auto drain = [&] {
    while (!open.empty() || !numeric_support.empty()) {
      if (open.empty()) {
        const ActionId a = numeric_support.back();
        numeric_support.pop_back();
        if (rpg_.actions_[a].durative) {
          count_end(a);
        } else {
          count_start(a);
        }
        continue;
      }
      const FactId f = open.back();
      open.pop_back();
      if (processed_.at(f, generation_) == 2) continue;
      processed_.at(f, generation_) = 2;  // 2: supported in the relaxed plan
      const Achiever a = achiever_.at(f, generation_);
      switch (a.kind) {
        case AchieverKind::Start:
        case AchieverKind::Instant: count_start(a.index); break;
        case AchieverKind::End: count_end(a.index); break;
        case AchieverKind::Axiom: {
          const std::vector<FactId>& body = task.axioms[a.index].body.positive;
          open.insert(open.end(), body.begin(), body.end());
          break;
        }
        default: break;
      }
    }
  };
  drain();
  double extra = 0.0;
  short_variables_.clear();
  if (balance_) {
    for (ActionId producer : shortfall_producers(state, extra)) {
      if (rpg_.actions_[producer].durative) {
        count_end(producer);
      } else {
        count_start(producer);
      }
    }
    drain();
  }
  count += extra;
  // The further applications of constant producers the unmet comparisons ask.
  for (const auto& [a, times] : repetitions_) {
    count += (times - 1.0) * (rpg_.actions_[a].durative ? 2.0 : 1.0);
    if (metric) value.cost += (times - 1.0) * (metric->start_cost[a] + metric->end_cost[a]);
  }
  // Every running action still owes its end.
  for (const RunningAction& r : state.running()) {
    if (!counted_end_.at(r.action, generation_)) count += 1.0;
    if (metric) value.cost += metric->end_cost[r.action];
  }
  value.h = count;
  if (rpg_.options_.helpful_actions) add_helpful(state, value);
  return value;
}

// Helpful: relaxed-plan snaps whose preconditions hold now.
void TemporalRpg::Exploration::add_helpful(const SearchState& state, HeuristicValue& value) {
  const GroundTask& task = rpg_.index_.task();
  auto holds_now = [&](const std::vector<FactId>& pre) {
    return std::all_of(pre.begin(), pre.end(), [&](FactId f) { return state.fact(f); });
  };
  for (ActionId a = 0; a < rpg_.actions_.size(); ++a) {
    if (counted_end_.stamps[a] == generation_ && counted_end_.values[a] && state.is_running(a) &&
        holds_now(rpg_.actions_[a].end_pre)) {
      value.helpful.push_back({SnapKind::End, a});
    }
    if (counted_start_.stamps[a] == generation_ && counted_start_.values[a] &&
        holds_now(task.actions[a].at_start.positive)) {
      value.helpful.push_back({rpg_.actions_[a].durative ? SnapKind::Start : SnapKind::Instant, a});
    }
  }
}

}  // namespace alplan
