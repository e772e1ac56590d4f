#include "planner/partial_plan.h"

#include <algorithm>

namespace alplan {
namespace {

bool intersects(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
  auto i = a.begin(), j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i == *j) return true;
    if (*i < *j) ++i; else ++j;
  }
  return false;
}

bool contains(const std::vector<std::uint32_t>& v, std::uint32_t k) { return std::binary_search(v.begin(), v.end(), k); }

const std::vector<std::uint32_t> kNoKeys;

// Whether `ender`'s end deletes (and does not give back) a fact `holder`
// needs over all: `ender` may not end while `holder` runs.
bool end_threatens(const GroundAction& ender, const GroundAction& holder) {
  for (FactId f : holder.over_all.positive) {
    if (std::find(ender.end.del.begin(), ender.end.del.end(), f) != ender.end.del.end() &&
        std::find(ender.end.add.begin(), ender.end.add.end(), f) == ender.end.add.end()) {
      return true;
    }
  }
  return false;
}

}  // namespace

PartialPlan::PartialPlan(const TaskIndex& index, double epsilon, double release,
                         const std::vector<RunningAction>& running, const std::vector<double>& values)
    : index_(&index), epsilon_(epsilon), release_(release) {
  if (index.continuous()) {
    continuous_.emplace(index.continuous(), values.empty() ? index.task().initial_values : values);
  }
  for (const RunningAction& r : running) {
    const std::uint32_t node = network_.size();
    std::vector<TemporalEdge> edges{{0, node, std::max(r.min_duration, release_)}};
    if (r.max_duration < kInfiniteDuration) edges.push_back({node, 0, -r.max_duration});
    network_.add_nodes(1, edges);
    pending_.push_back({r.action, node, 0, r.max_duration});
  }
}

PartialPlan::Touch PartialPlan::fact_touch(const Footprint& fp) {
  return {fp.reads, fp.holds, fp.writes, fp.adds, fp.dels, fp.reads_first};
}

PartialPlan::Touch PartialPlan::value_touch(const Footprint& fp) {
  return {fp.reads_values, fp.holds_values, fp.writes_values, fp.additive_values, kNoKeys, fp.reads_first_values};
}

PartialPlan::WriteKind PartialPlan::Touch::kind_of(std::uint32_t key) const {
  if (contains(adds, key)) return WriteKind::Add;
  if (contains(dels, key)) return WriteKind::Delete;
  return WriteKind::Other;
}

const PartialPlan::Use* PartialPlan::Ledger::last_write(std::uint32_t key) const {
  auto it = std::lower_bound(writers.begin(), writers.end(), key,
                             [](const Use& u, std::uint32_t k) { return u.key < k; });
  if (it == writers.end() || it->key != key) return nullptr;
  return &*it;
}

std::optional<std::uint32_t> PartialPlan::Ledger::writer(std::uint32_t key) const {
  const Use* w = last_write(key);
  if (!w) return std::nullopt;
  return w->step;
}

// Readers come epsilon after the last writer, holders with no gap; a writer
// comes after the last writer (no gap when both write the key the same one
// way) and after every reader since (epsilon) and holder since (no gap).
void PartialPlan::Ledger::add_constraints(const Touch& touch, std::uint32_t node, double epsilon,
                                          std::vector<TemporalEdge>& edges, std::vector<TemporalEdge>& loose,
                                          const std::vector<std::uint32_t>& node_of_step) const {
  auto add = [&](std::uint32_t from, double gap) {
    edges.push_back({from, node, gap});
    if (gap == 0.0) loose.push_back({from, node, epsilon});
  };
  for (const auto* read : {&touch.reads, &touch.reads_first}) {
    for (std::uint32_t key : *read) {
      if (const Use* w = last_write(key)) add(node_of_step[w->step], epsilon);
    }
  }
  for (std::uint32_t key : touch.holds) {
    if (const Use* w = last_write(key)) add(node_of_step[w->step], 0.0);
  }
  for (std::uint32_t key : touch.writes) {
    const Use* w = last_write(key);
    const WriteKind kind = touch.kind_of(key);
    if (w) {
      const bool alike = kind != WriteKind::Other && kind == w->kind;
      add(node_of_step[w->step], alike ? 0.0 : epsilon);
    }
    // Only reads since the last write of a key are kept (record()).
    const auto [first, last] = reads_of(key);
    for (auto r = first; r != last; ++r) add(node_of_step[r->step], r->kind == WriteKind::Add ? 0.0 : epsilon);
  }
}

std::pair<std::vector<PartialPlan::Use>::const_iterator, std::vector<PartialPlan::Use>::const_iterator>
PartialPlan::Ledger::reads_of(std::uint32_t key) const {
  const auto first = std::lower_bound(reads.begin(), reads.end(), key,
                                      [](const Use& u, std::uint32_t k) { return u.key < k; });
  const auto last = std::upper_bound(first, reads.end(), key, [](std::uint32_t k, const Use& u) { return k < u.key; });
  return {first, last};
}

// Reads are kept sorted by key, in the order of their steps within a key,
// and only since the key's last write: every later constraint and the
// interface look at no older read, and a plan rebuilt step by step from the
// root (SearchSpace::partial_plan) then costs time linear in its length,
// not quadratic.
void PartialPlan::Ledger::record(const Touch& touch, std::uint32_t step) {
  auto read = [&](std::uint32_t key, WriteKind kind) {
    const auto at = std::upper_bound(reads.begin(), reads.end(), key,
                                     [](std::uint32_t k, const Use& u) { return k < u.key; });
    reads.insert(at, {key, step, kind});
  };
  for (std::uint32_t key : touch.reads) read(key, WriteKind::Other);
  // Later writers may share the happening of a holder or a first reader.
  for (std::uint32_t key : touch.holds) read(key, WriteKind::Add);
  for (std::uint32_t key : touch.reads_first) read(key, WriteKind::Add);
  for (std::uint32_t key : touch.writes) {
    const auto [first, last] = reads_of(key);
    reads.erase(first, last);
    const WriteKind kind = touch.kind_of(key);
    auto it = std::lower_bound(writers.begin(), writers.end(), key,
                               [](const Use& u, std::uint32_t k) { return u.key < k; });
    if (it != writers.end() && it->key == key) {
      it->step = step;
      it->kind = kind;
    } else {
      writers.insert(it, {key, step, kind});
    }
  }
}

bool PartialPlan::zero_duration_together(ActionId action) const {
  // Conditional effects whose condition reads what the other snap writes
  // are left out: the successor generator requires their conditions false
  // in the state before the happening, where VAL then neither counts the
  // reads nor applies the effects.
  if (const TaskIndex::CrossConditionals* cross = index_->cross_conditionals(action)) {
    return separation(cross->start_footprint, cross->end_footprint).value_or(0.0) == 0.0;
  }
  return separation(index_->footprint({SnapKind::Start, action}), index_->footprint({SnapKind::End, action}))
             .value_or(0.0) == 0.0;
}

std::optional<double> PartialPlan::separation(const Footprint& a, const Footprint& b) const {
  std::optional<double> gap;
  auto need = [&](double g) { gap = std::max(gap.value_or(0.0), g); };
  for (const auto& [ta, tb] : {std::pair{fact_touch(a), fact_touch(b)}, std::pair{value_touch(a), value_touch(b)}}) {
    if (intersects(ta.writes, tb.reads) || intersects(ta.reads, tb.writes)) need(epsilon_);
    if (intersects(ta.writes, tb.holds) || intersects(ta.holds, tb.writes)) need(0.0);
    if (intersects(ta.writes, tb.reads_first)) need(epsilon_);
    if (intersects(ta.reads_first, tb.writes)) need(0.0);
    for (std::uint32_t key : ta.writes) {
      if (!contains(tb.writes, key)) continue;
      const WriteKind ka = ta.kind_of(key), kb = tb.kind_of(key);
      need(ka != WriteKind::Other && ka == kb ? 0.0 : epsilon_);
    }
  }
  return gap;
}

void PartialPlan::order_before_pending(const Footprint& fp, std::uint32_t node, std::size_t except,
                                       std::vector<TemporalEdge>& edges) const {
  for (std::size_t i = 0; i < pending_.size(); ++i) {
    const PendingEnd& p = pending_[i];
    if (i == except) continue;
    if (const auto gap = separation(fp, index_->footprint({SnapKind::End, p.action}))) {
      edges.push_back({node, p.node, *gap});
    }
  }
}

void PartialPlan::replay(const StepRecord& step) {
  replaying_ = true;
  append(step);
  replaying_ = false;
}

void PartialPlan::settle() {
  if (continuous_) continuous_->resolve(network_);
}

bool PartialPlan::append(const StepRecord& step) {
  const std::uint32_t index = static_cast<std::uint32_t>(steps_.size());
  const Footprint& fp = index_->footprint(step.snap, step.quiet);
  std::vector<TemporalEdge> edges;
  std::uint32_t node = network_.size();
  std::uint32_t new_nodes = 1;
  std::size_t ending = pending_.size();
  if (step.snap.kind == SnapKind::End) {
    // The run this end closes: the one its start step began (an action may
    // run twice at once), or one running since before the plan.
    const std::uint32_t start_node = step.start_step == kNoId ? 0 : node_of_step_[step.start_step];
    auto found = std::find_if(pending_.begin(), pending_.end(), [&](const PendingEnd& p) {
      return p.action == step.snap.index && p.start_node == start_node;
    });
    if (found == pending_.end()) return false;  // not running
    ending = static_cast<std::size_t>(found - pending_.begin());
    node = found->node;
    new_nodes = 0;
    // Bounds found only at the end (at-end duration constraints) tighten it.
    const std::uint32_t start = step.start_step == kNoId ? 0 : node_of_step_[step.start_step];
    edges.push_back({start, node, step.min_duration});
    if (step.max_duration < kInfiniteDuration) edges.push_back({node, start, -step.max_duration});
  } else {
    edges.push_back({0, node, release_});
  }
  std::vector<TemporalEdge> loose;
  facts_.add_constraints(fact_touch(fp), node, epsilon_, edges, loose, node_of_step_);
  values_.add_constraints(value_touch(fp), node, epsilon_, edges, loose, node_of_step_);
  order_before_pending(fp, node, ending, edges);
  if (step.simultaneous_with != kNoId) {
    // One happening with that step: the same time, and members VAL would
    // not call a mutex.
    const StepRecord& other = steps_[step.simultaneous_with];
    if (separation(index_->footprint(other.snap, other.quiet), fp).value_or(0.0) > 0.0) return false;
    const std::uint32_t other_node = node_of_step_[step.simultaneous_with];
    edges.push_back({other_node, node, 0.0});
    edges.push_back({node, other_node, 0.0});
  }
  if (step.snap.kind == SnapKind::End && step.max_duration == 0.0 && step.start_step != kNoId &&
      zero_duration_together(step.snap.index)) {
    // A zero-duration action's start and end form one happening; unless
    // they interfere as VAL judges two members of a happening (then the
    // separation makes it unschedulable, as VAL refuses it), nothing
    // separates them.
    const std::uint32_t start_node = node_of_step_[step.start_step];
    std::erase_if(edges, [&](const TemporalEdge& e) { return e.from == start_node && e.to == node && e.weight > 0.0; });
  }
  if (step.snap.kind == SnapKind::TimedLiteral) {
    // Timed literals keep the order of their times: no separation between
    // two of them (two at one time deleting one fact are one happening).
    std::erase_if(edges, [&](const TemporalEdge& e) { return e.from != 0 && is_timed_literal_node(e.from); });
    const double at = index_->task().timed_literals[step.snap.index].time;
    edges.push_back({0, node, at});
    edges.push_back({node, 0, -at});
  }
  if (step.snap.kind == SnapKind::Start) {
    // The end joins the network now: after its start by the duration, after
    // everything so far that it interferes with (it comes later in the plan).
    const std::uint32_t end = node + 1;
    new_nodes = 2;
    edges.push_back({node, end, step.min_duration});
    if (step.max_duration < kInfiniteDuration) edges.push_back({end, node, -step.max_duration});
    const Footprint& end_fp = index_->footprint({SnapKind::End, step.snap.index});
    facts_.add_constraints(fact_touch(end_fp), end, epsilon_, edges, loose, node_of_step_);
    values_.add_constraints(value_touch(end_fp), end, epsilon_, edges, loose, node_of_step_);
    // The new start itself precedes the ends of the others it touches.
    // An end that would break a running action's invariant can come only
    // after that action's end (the successor generator refuses it before),
    // or with it (VAL checks no invariant at its action's end): said now, a
    // start that cannot finish before such an end fails here, not many
    // steps below (a bake in a firing too short for it).
    const GroundAction& started = index_->task().actions[step.snap.index];
    for (const PendingEnd& p : pending_) {
      const GroundAction& other = index_->task().actions[p.action];
      if (end_threatens(other, started)) {
        edges.push_back({end, p.node, 0.0});
        loose.push_back({end, p.node, epsilon_});
      }
      if (end_threatens(started, other)) {
        edges.push_back({p.node, end, 0.0});
        loose.push_back({p.node, end, epsilon_});
      }
    }
  }
  std::vector<NumericVarId> invariant_reads;
  if (continuous_) {
    // Over-all conditions this snap checks read their variables at its time.
    const SnapNodes at = snap_nodes(step, node);
    if (step.continuous) invariant_reads = continuous_->invariant_reads(*step.continuous, at);
    if (!invariant_reads.empty()) {
      values_.add_constraints({invariant_reads, kNoKeys, kNoKeys, kNoKeys, kNoKeys, kNoKeys}, node, epsilon_, edges, loose,
                              node_of_step_);
      Footprint reads;
      reads.reads_values = invariant_reads;
      order_before_pending(reads, node, ending, edges);
    }
    const SimpleTemporalNetwork before = network_;
    if (!network_.add_nodes(new_nodes, edges)) return false;
    // An end with nothing of its own still stops its action's change.
    static const ContinuousStep kNothing;
    const bool scheduled = step.snap.kind == SnapKind::TimedLiteral
                               ? replaying_ || continuous_->resolve(network_)
                               : continuous_->add(step.continuous ? *step.continuous : kNothing, at, network_,
                                                  !replaying_);
    if (!scheduled) {
      network_ = before;
      return false;
    }
  } else if (!network_.add_nodes(new_nodes, edges)) {
    return false;
  }
  loose_.insert(loose_.end(), loose.begin(), loose.end());
  values_.record({invariant_reads, kNoKeys, kNoKeys, kNoKeys, kNoKeys, kNoKeys}, index);
  facts_.record(fact_touch(fp), index);
  values_.record(value_touch(fp), index);
  steps_.push_back(step);
  node_of_step_.push_back(node);
  if (step.snap.kind == SnapKind::TimedLiteral) timed_literal_nodes_.push_back(node);
  if (ending < pending_.size()) pending_.erase(pending_.begin() + static_cast<std::ptrdiff_t>(ending));
  if (step.snap.kind == SnapKind::Start) pending_.push_back({step.snap.index, node + 1, node, step.max_duration});
  return true;
}

bool PartialPlan::is_timed_literal_node(std::uint32_t node) const {
  return std::find(timed_literal_nodes_.begin(), timed_literal_nodes_.end(), node) != timed_literal_nodes_.end();
}

double PartialPlan::node_time(std::uint32_t node) const {
  return continuous_ && continuous_->active() ? continuous_->time(node) : network_.earliest(node);
}

SnapNodes PartialPlan::snap_nodes(const StepRecord& step, std::uint32_t node) const {
  SnapNodes at{step.snap.kind, step.snap.index, node, node, node};
  if (step.snap.kind == SnapKind::Start) at.end_node = node + 1;
  if (step.snap.kind == SnapKind::End) {
    for (const PendingEnd& p : pending_) {
      if (p.action == step.snap.index) at.start_node = p.start_node;
    }
  }
  return at;
}

bool PartialPlan::require_final(const std::vector<LinearCondition>& conditions) {
  if (!continuous_) return conditions.empty();
  return continuous_->require_final(conditions, network_);
}

void PartialPlan::set_changing_values(SearchState& state) const {
  if (!continuous_ || node_of_step_.empty()) return;
  const ContinuousModel& model = *index_->continuous();
  for (NumericVarId v = 0; v < state.values().size(); ++v) {
    if (model.changing(v)) state.set_value(v, continuous_->value_at(v, continuous_->last_change(v)));
  }
}

std::pair<double, double> PartialPlan::changing_bounds(NumericVarId v, double value, bool least,
                                                      bool greatest) const {
  if (!continuous_ || !index_->continuous()->changing(v)) return {value, value};
  return continuous_->bounds(v, continuous_->last_change(v), network_, least, greatest);
}

double PartialPlan::changing_value_time(NumericVarId v) const {
  if (!continuous_ || node_of_step_.empty()) return 0.0;
  return continuous_->time(continuous_->last_change(v));
}

std::vector<std::pair<ActionId, std::vector<NumericVarId>>> PartialPlan::invariants_failing_at_end() const {
  if (!continuous_) return {};
  return continuous_->failing_at_end(network_);
}

double PartialPlan::pending_end_time(ActionId action) const {
  double earliest = std::numeric_limits<double>::infinity();
  for (const PendingEnd& p : pending_) {
    if (p.action == action) earliest = std::min(earliest, node_time(p.node));
  }
  return earliest == std::numeric_limits<double>::infinity() ? 0.0 : earliest;
}

std::vector<double> PartialPlan::latest_end_times(const std::vector<RunningAction>& running) const {
  std::vector<double> latest_end(running.size(), kInfiniteDuration), latest_start(running.size(), kInfiniteDuration);
  std::vector<const PendingEnd*> pending(running.size(), nullptr);
  // Per network node, 1 + the index in `running` of the action it starts or
  // ends there (0: none).
  std::vector<std::uint32_t> starting(network_.size(), 0), ending(network_.size(), 0);
  for (std::uint32_t i = 0; i < running.size(); ++i) {
    const ActionId action = running[i].action;
    const std::uint32_t step = running[i].start_step;
    const std::uint32_t start_node = step == kNoId || step >= node_of_step_.size() ? 0 : node_of_step_[step];
    auto p = std::find_if(pending_.begin(), pending_.end(),
                          [&](const PendingEnd& e) { return e.action == action && e.start_node == start_node; });
    if (p == pending_.end()) continue;
    pending[i] = &*p;
    if (p->start_node == 0) latest_start[i] = 0.0;
    else starting[p->start_node] = i + 1;
    ending[p->node] = i + 1;
  }
  for (const TemporalEdge& e : network_.edges()) {
    if (const std::uint32_t i = starting[e.from]; i != 0 && e.to != pending[i - 1]->node) {
      latest_start[i - 1] = std::min(latest_start[i - 1], network_.earliest(e.to) - e.weight);
    }
    if (const std::uint32_t i = ending[e.from]; i != 0 && e.to != pending[i - 1]->start_node) {
      latest_end[i - 1] = std::min(latest_end[i - 1], network_.earliest(e.to) - e.weight);
    }
  }
  for (std::size_t i = 0; i < running.size(); ++i) {
    if (pending[i] && pending[i]->max_duration < kInfiniteDuration) {
      latest_end[i] = std::min(latest_end[i], latest_start[i] + pending[i]->max_duration);
    }
  }
  return latest_end;
}

std::vector<double> PartialPlan::preferred_times() const {
  std::vector<double> times;
  if (continuous_ && continuous_->active()) {
    for (std::uint32_t s = 0; s < steps_.size(); ++s) times.push_back(time_of(s));
    return times;
  }
  // Epsilon on each loose edge in turn, kept where the network stays
  // consistent: greedy, so the first edges of the plan get it first.
  SimpleTemporalNetwork preferred = network_;
  for (const TemporalEdge& e : loose_) {
    if (preferred.earliest(e.to) >= preferred.earliest(e.from) + e.weight - 1e-12) continue;
    preferred.add_edges({e});
  }
  for (std::uint32_t s = 0; s < steps_.size(); ++s) times.push_back(preferred.earliest(node_of_step_[s]));
  return times;
}

double PartialPlan::frontier() const {
  double latest = 0.0;
  for (std::uint32_t s = 0; s < steps_.size(); ++s) {
    if (steps_[s].snap.kind != SnapKind::TimedLiteral) latest = std::max(latest, time_of(s));
  }
  return latest;
}

double PartialPlan::makespan() const {
  double latest = 0.0;
  for (std::uint32_t s = 0; s < steps_.size(); ++s) {
    if (steps_[s].snap.kind != SnapKind::TimedLiteral) latest = std::max(latest, time_of(s));
  }
  for (const PendingEnd& p : pending_) latest = std::max(latest, node_time(p.node));
  return latest;
}

double PartialPlan::available_from(FactId fact, double gap) const {
  if (auto w = facts_.writer(fact)) return time_of(*w) + gap;
  return release_;
}

}  // namespace alplan
