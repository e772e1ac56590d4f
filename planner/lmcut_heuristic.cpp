#include "planner/lmcut_heuristic.h"

#include <algorithm>
#include <functional>
#include <limits>

namespace alplan {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Costs are sums of the metric's constants; what is left of one after a
// cut below this is zero.
constexpr double kZero = 1e-9;

std::vector<std::uint32_t> sorted_unique(std::vector<std::uint32_t> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

void append_adds(const HappeningEffects& effects, std::vector<std::uint32_t>& out) {
  out.insert(out.end(), effects.add.begin(), effects.add.end());
  for (const ConditionalEffect& c : effects.conditional) out.insert(out.end(), c.add.begin(), c.add.end());
}

}  // namespace

LmCutHeuristic::LmCutHeuristic(const TaskIndex& index, std::shared_ptr<const LinearMetric> metric)
    : index_(index), metric_(std::move(metric)) {
  const GroundTask& task = index_.task();
  const auto facts = static_cast<Node>(task.facts.size());
  start_node_ = facts;
  goal_node_ = facts + 1;
  precondition_of_.resize(facts + 2);
  achievers_.resize(facts + 2);
  end_operator_.assign(task.actions.size(), kNoId);
  for (ActionId a = 0; a < task.actions.size(); ++a) {
    const GroundAction& action = task.actions[a];
    if (action.at_start.never || action.over_all.never || action.at_end.never) continue;
    std::vector<Node> later = action.over_all.positive;
    later.insert(later.end(), action.at_end.positive.begin(), action.at_end.positive.end());
    std::vector<Node> pre = action.at_start.positive;
    const std::vector<Node> own = sorted_unique(action.start.add);
    for (Node f : later) {
      if (!std::binary_search(own.begin(), own.end(), f)) pre.push_back(f);
    }
    std::vector<Node> add;
    append_adds(action.start, add);
    append_adds(action.end, add);
    const double cost = metric_ ? metric_->start_cost[a] + metric_->end_cost[a] : 1.0;
    add_operator(std::move(pre), std::move(add), cost, kNoId);
    if (action.durative) {
      std::vector<Node> end_add;
      append_adds(action.end, end_add);
      end_operator_[a] = static_cast<std::uint32_t>(operators_.size());
      add_operator(std::move(later), std::move(end_add), 0.0, a);
    }
  }
  for (const GroundAxiom& axiom : task.axioms) {
    if (!axiom.body.never) add_operator(axiom.body.positive, {axiom.head}, 0.0, kNoId);
  }
  if (!task.goal.never) add_operator(task.goal.positive, {goal_node_}, 0.0, kNoId);
  for (const GroundTimedLiteral& til : task.timed_literals) {
    if (til.positive) til_adds_.push_back(til.fact);
  }
  const std::size_t nodes = facts + 2, ops = operators_.size();
  cost_.resize(ops);
  op_value_.resize(ops);
  unsatisfied_.resize(ops);
  pcf_.resize(ops);
  enabled_.resize(ops);
  in_cut_.assign(ops, 0);
  hmax_.resize(nodes);
  root_.resize(nodes);
  zone_.resize(nodes);
  reached_.resize(nodes);
}

void LmCutHeuristic::add_operator(std::vector<Node> pre, std::vector<Node> add, double cost, ActionId running_end) {
  pre = sorted_unique(std::move(pre));
  if (pre.empty()) pre.push_back(start_node_);
  add = sorted_unique(std::move(add));
  const auto id = static_cast<std::uint32_t>(operators_.size());
  for (Node f : pre) precondition_of_[f].push_back(id);
  for (Node f : add) achievers_[f].push_back(id);
  operators_.push_back({std::move(pre), std::move(add), std::max(0.0, cost), running_end});
}

bool LmCutHeuristic::compute_hmax() {
  std::fill(hmax_.begin(), hmax_.end(), kInfinity);
  std::fill(op_value_.begin(), op_value_.end(), kInfinity);
  for (std::uint32_t o = 0; o < operators_.size(); ++o) unsatisfied_[o] = static_cast<std::uint32_t>(operators_[o].pre.size());
  // A heap in a kept vector: this runs once per cut of every evaluation.
  std::vector<HeapEntry>& open = heap_;
  open.clear();
  const auto push = [&](double value, Node node) {
    open.emplace_back(value, node);
    std::push_heap(open.begin(), open.end(), std::greater<>());
  };
  for (Node r : roots_) {
    hmax_[r] = 0.0;
    push(0.0, r);
  }
  while (!open.empty()) {
    std::pop_heap(open.begin(), open.end(), std::greater<>());
    const auto [value, node] = open.back();
    open.pop_back();
    if (value > hmax_[node]) continue;
    // Facts leave in order of their cost, so an operator's last
    // precondition to leave is its costliest.
    for (std::uint32_t o : precondition_of_[node]) {
      if (!enabled_[o] || --unsatisfied_[o] != 0) continue;
      op_value_[o] = value + cost_[o];
      for (Node e : operators_[o].add) {
        if (op_value_[o] < hmax_[e]) {
          hmax_[e] = op_value_[o];
          push(op_value_[o], e);
        }
      }
    }
  }
  return hmax_[goal_node_] != kInfinity;
}

double LmCutHeuristic::cut_once() {
  if (hmax_[goal_node_] <= kZero) return 0.0;
  const auto applicable = [&](std::uint32_t o) { return enabled_[o] && unsatisfied_[o] == 0; };
  for (std::uint32_t o = 0; o < operators_.size(); ++o) {
    if (!applicable(o)) continue;
    Node best = operators_[o].pre.front();
    for (Node f : operators_[o].pre) {
      if (hmax_[f] > hmax_[best]) best = f;
    }
    pcf_[o] = best;
  }
  // The goal zone: what reaches the goal by operators that cost nothing.
  std::fill(zone_.begin(), zone_.end(), 0);
  std::vector<Node>& stack = work_;
  stack.assign(1, goal_node_);
  zone_[goal_node_] = 1;
  while (!stack.empty()) {
    const Node e = stack.back();
    stack.pop_back();
    for (std::uint32_t o : achievers_[e]) {
      if (applicable(o) && cost_[o] <= kZero && !zone_[pcf_[o]]) {
        zone_[pcf_[o]] = 1;
        stack.push_back(pcf_[o]);
      }
    }
  }
  // From the state, through chosen preconditions, short of the zone: the
  // operators that cross into it are the cut, a landmark.
  std::fill(reached_.begin(), reached_.end(), 0);
  std::vector<Node>& queue = work_;
  queue.clear();
  for (Node r : roots_) {
    if (!zone_[r] && !reached_[r]) reached_[r] = 1, queue.push_back(r);
  }
  std::vector<std::uint32_t>& cut = cut_;
  cut.clear();
  for (std::size_t next = 0; next < queue.size(); ++next) {
    const Node f = queue[next];
    for (std::uint32_t o : precondition_of_[f]) {
      if (!applicable(o) || pcf_[o] != f) continue;
      for (Node e : operators_[o].add) {
        if (zone_[e]) {
          if (!in_cut_[o]) in_cut_[o] = 1, cut.push_back(o);
        } else if (!reached_[e]) {
          reached_[e] = 1;
          queue.push_back(e);
        }
      }
    }
  }
  if (cut.empty()) return 0.0;  // cannot happen while the goal costs something; stop rather than loop
  double least = kInfinity;
  for (std::uint32_t o : cut) least = std::min(least, cost_[o]);
  for (std::uint32_t o : cut) {
    cost_[o] -= least;
    in_cut_[o] = 0;
  }
  return least;
}

double LmCutHeuristic::estimate(const SearchState& state) {
  const GroundTask& task = index_.task();
  for (std::uint32_t o = 0; o < operators_.size(); ++o) {
    cost_[o] = operators_[o].base_cost;
    enabled_[o] = operators_[o].action == kNoId;
  }
  double owed = 0.0;
  for (const RunningAction& r : state.running()) {
    if (end_operator_[r.action] != kNoId) enabled_[end_operator_[r.action]] = 1;
    if (metric_) owed += metric_->end_cost[r.action];
  }
  roots_.clear();
  std::fill(root_.begin(), root_.end(), 0);
  const auto add_root = [&](Node n) {
    if (!root_[n]) root_[n] = 1, roots_.push_back(n);
  };
  add_root(start_node_);
  for (Node f = 0; f < task.facts.size(); ++f) {
    if (state.fact(f)) add_root(f);
  }
  for (Node f : til_adds_) add_root(f);
  unreached_.clear();
  if (task.goal.never || !compute_hmax()) {
    for (FactId g : task.goal.positive) {
      if (hmax_[g] == kInfinity) unreached_.push_back(g);
    }
    return kInfinity;
  }
  double h = 0.0;
  while (const double cut = cut_once()) {
    h += cut;
    compute_hmax();
  }
  return owed + h;
}

HeuristicValue LmCutHeuristic::evaluate(const SearchState& state, const PartialPlan& plan, Relaxation) {
  HeuristicValue value;
  value.relaxed_makespan = plan.makespan();
  const double remaining = estimate(state);
  if (remaining == kInfinity) return value;  // h stays infinite: a dead end
  bool goal = state.running().empty();
  for (FactId f : index_.task().goal.positive) goal = goal && state.fact(f);
  for (FactId f : index_.task().goal.negative) goal = goal && !state.fact(f);
  value.h = goal ? 0.0 : 1.0 + remaining;
  if (metric_) value.cost = remaining;
  return value;
}

}  // namespace alplan
