#include "planner/search_space.h"

#include <algorithm>

#include "planner/formula_evaluation.h"

namespace alplan {

bool schedules_can_close_doors(const GroundTask& task, const SearchState& start) {
  if (!task.timed_literals.empty()) return true;
  for (const RunningAction& r : start.running()) {
    if (r.max_duration < kInfiniteDuration) return true;
  }
  for (const GroundAction& a : task.actions) {
    if (!a.continuous.empty()) return true;
    for (const GroundDurationConstraint& d : a.duration) {
      if (d.comparison != pddl::Comparison::GreaterEqual && d.comparison != pddl::Comparison::Greater) return true;
    }
  }
  return false;
}

bool SearchSpace::timed_literals_remain(const SearchState& state) const {
  return state.next_timed_literal() < index_.task().timed_literals.size();
}

SearchSpace::SearchSpace(const TaskIndex& index, const SearchStart& start, double epsilon, SearchSpaceOptions options)
    : index_(index),
      successors_(index, options.self_overlap, options.simultaneous_invariants),
      epsilon_(epsilon),
      release_(start.release),
      options_(options),
      deadlines_(!index.task().timed_literals.empty()),
      schedules_matter_(options.exact_duplicates && schedules_can_close_doors(index.task(), start.state)) {
  SearchNode root;
  root.state = start.state;
  nodes_.push_back(std::move(root));
  const PartialPlan root_plan = partial_plan(0);
  nodes_.back().signature = signature_of(nodes_.back().state, root_plan);
  if (schedules_matter_) {
    nodes_.back().interface = std::make_shared<const PartialPlan::Interface>(
        root_plan.interface(timed_literals_remain(nodes_.back().state)));
  }
  seen_[&nodes_.back().state].push_back(0);
}

TemporalSignature SearchSpace::signature_of(const SearchState& state, const PartialPlan& plan) {
  TemporalSignature signature;
  signature.frontier = plan.frontier();
  signature.latest_ends = plan.latest_end_times(state.running());
  return signature;
}

bool SearchSpace::dominated(const SearchNode& candidate, NodeId stored) const {
  constexpr double kTolerance = 1e-9;
  if (options_.exact_duplicates) {
    // Without deadlines or upper bounds every sequence of snaps can be
    // scheduled (all constraints are lower bounds), so the state decides.
    if (!schedules_matter_) return true;
    return nodes_[stored].interface->allows_all_of(*candidate.interface);
  }
  const TemporalSignature& a = nodes_[stored].signature;
  const TemporalSignature& b = candidate.signature;
  if (deadlines_ && a.frontier > b.frontier + kTolerance) return false;
  for (std::size_t i = 0; i < a.latest_ends.size() && i < b.latest_ends.size(); ++i) {
    if (a.latest_ends[i] < b.latest_ends[i] - kTolerance) return false;
  }
  return true;
}

PartialPlan SearchSpace::partial_plan(NodeId id) const {
  std::vector<const StepRecord*> chain;
  for (NodeId n = id; n != 0; n = nodes_[n].parent) chain.push_back(&nodes_[n].step);
  PartialPlan plan(index_, epsilon_, release_, nodes_[0].state.running(), nodes_[0].state.values());
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    // Every stored step was consistent when it was added; appending the same
    // steps in the same order reproduces the same network.
    plan.replay(**it);
  }
  plan.settle();
  return plan;
}

std::vector<Successor> SearchSpace::successors(NodeId id, SearchStatistics& stats) const {
  std::vector<Successor> successors;
  successors_.generate(nodes_[id].state, successors);
  stats.generated += successors.size();
  return successors;
}

std::optional<Child> SearchSpace::schedule(NodeId id, const PartialPlan& plan, Successor s,
                                           SearchStatistics& stats) const {
  PartialPlan extended = plan;
  if (!extended.append(s.step)) {
    ++stats.unschedulable;
    return std::nullopt;
  }
  if (s.step.snap.kind == SnapKind::Start) {
    s.state.set_start_step(s.step.snap.index, static_cast<std::uint32_t>(extended.size() - 1));
  }
  s.state.set_step(static_cast<std::uint32_t>(extended.size() - 1));
  extended.set_changing_values(s.state);
  Child child{SearchNode{}, std::move(extended)};
  child.node.parent = id;
  child.node.step = s.step;
  child.node.state = std::move(s.state);
  child.node.depth = nodes_[id].depth + 1;
  child.node.makespan = child.plan.makespan();
  child.node.signature = signature_of(child.node.state, child.plan);
  if (schedules_matter_) {
    child.node.interface =
        std::make_shared<const PartialPlan::Interface>(child.plan.interface(timed_literals_remain(child.node.state)));
  }
  return child;
}

std::vector<Child> SearchSpace::children(NodeId id, const PartialPlan& plan, SearchStatistics& stats) const {
  std::vector<Successor> all = successors(id, stats);
  std::vector<Child> result;
  result.reserve(all.size());
  for (Successor& s : all) {
    if (std::optional<Child> child = schedule(id, plan, std::move(s), stats)) result.push_back(std::move(*child));
  }
  return result;
}

bool SearchSpace::evaluate_node(SearchNode& node, const PartialPlan& plan, Heuristic& heuristic,
                                SearchStatistics& stats) const {
  ++stats.evaluated;
  if (orders_ && orders_->broken_by(node.state)) {
    node.h = std::numeric_limits<double>::infinity();
    node.helpful.clear();
    node.evaluated = true;
    ++stats.dead_ends;
    return false;
  }
  if (node.state.ends_open() && node.parent < nodes_.size()) {
    // A state inside a happening some end opened: running actions whose
    // invariant it broke must end in it (successor_generator.h), which no
    // relaxation knows (their ends need the invariant): the parent's
    // estimate stands for it, never a dead end.
    const SearchNode& parent = nodes_[node.parent];
    node.h = parent.h;
    node.helpful.clear();
    node.evaluated = true;
    node.makespan_bound = std::max(node.makespan, parent.makespan_bound);
    node.relaxed_cost = parent.relaxed_cost;
    return true;
  }
  HeuristicValue value = heuristic.evaluate(node.state, plan);
  if (value.dead_end() && options_.confirm_dead_ends) {
    // The guiding relaxation's dead end, confirmed or not by the sound one.
    HeuristicValue sound = heuristic.evaluate(node.state, plan, Relaxation::Sound);
    if (!sound.dead_end()) value = std::move(sound);
  }
  node.h = value.h;
  node.helpful = std::move(value.helpful);
  node.evaluated = true;
  // The relaxed graph may separate happenings by epsilon where a real plan
  // need not; the bound gives that back.
  node.makespan_bound = std::max(node.makespan, value.relaxed_makespan - epsilon_);
  node.relaxed_cost = value.cost;
  if (value.dead_end()) ++stats.dead_ends;
  return !value.dead_end();
}

bool SearchSpace::evaluate(Child& child, Heuristic& heuristic, SearchStatistics& stats) const {
  return evaluate_node(child.node, child.plan, heuristic, stats);
}

bool SearchSpace::evaluate_stored(NodeId id, const PartialPlan& plan, Heuristic& heuristic,
                                  SearchStatistics& stats) {
  return evaluate_node(nodes_[id], plan, heuristic, stats);
}

void SearchSpace::set_root_heuristic(Heuristic& heuristic, SearchStatistics& stats) {
  ++stats.evaluated;
  HeuristicValue value = heuristic.evaluate(nodes_[0].state, partial_plan(0));
  if (value.dead_end() && options_.confirm_dead_ends) {
    HeuristicValue sound = heuristic.evaluate(nodes_[0].state, partial_plan(0), Relaxation::Sound);
    if (!sound.dead_end()) value = std::move(sound);
  }
  nodes_[0].h = value.h;
  nodes_[0].helpful = std::move(value.helpful);
  nodes_[0].makespan_bound = std::max(nodes_[0].makespan, value.relaxed_makespan - epsilon_);
  nodes_[0].relaxed_cost = value.cost;
  nodes_[0].evaluated = true;
}

bool SearchSpace::known(const Child& child, SearchStatistics& stats) const {
  // Inside an open happening the members so far (their footprints, tied to
  // the opener's time) decide which snaps may still join, and a state does
  // not say which they are: such states are never pruned as duplicates.
  if (child.node.state.open_happening() != kNoId) return false;
  const auto it = seen_.find(&child.node.state);
  if (it == seen_.end()) return false;
  const bool duplicate =
      std::any_of(it->second.begin(), it->second.end(), [&](NodeId stored) { return dominated(child.node, stored); });
  if (duplicate) ++stats.duplicates;
  return duplicate;
}

std::optional<NodeId> SearchSpace::insert(Child child, SearchStatistics& stats) {
  if (known(child, stats)) return std::nullopt;
  nodes_.push_back(std::move(child.node));
  const auto id = static_cast<NodeId>(nodes_.size() - 1);
  // An equal state stored before keeps its key; this node joins its list.
  seen_[&nodes_.back().state].push_back(id);
  return id;
}

std::optional<NodeId> SearchSpace::find(const SearchState& state) const {
  auto it = seen_.find(&state);
  if (it == seen_.end()) return std::nullopt;
  return it->second.front();
}

std::optional<Solution> SearchSpace::goal_reached(NodeId id, const PartialPlan& plan) const {
  const SearchNode& n = nodes_[id];
  if (!n.state.running().empty()) return std::nullopt;
  SearchState state = n.state;
  PartialPlan complete = plan;
  while (state.next_timed_literal() < index_.task().timed_literals.size()) {
    const StepRecord step{{SnapKind::TimedLiteral, state.next_timed_literal()}};
    std::optional<SearchState> next = successors_.apply(state, step);
    if (!next || !complete.append(step)) return std::nullopt;
    state = std::move(*next);
  }
  if (const ContinuousModel* model = index_.continuous().get()) {
    if (!model->holds_fixed_part(index_.task().goal, state, std::nan(""))) return std::nullopt;
    const std::optional<std::vector<LinearCondition>> final_conditions = model->goal(index_.task().goal, state);
    if (!final_conditions || !complete.require_final(*final_conditions)) return std::nullopt;
  } else {
    try {
      if (!holds(index_.task().goal, state, EvaluationContext{}, 0.0)) return std::nullopt;
    } catch (const EvaluationError&) {
      return std::nullopt;
    }
  }
  Solution solution;
  solution.search_makespan = n.makespan;
  solution.final_state = state;
  solution.steps = complete.steps();
  solution.times = complete.preferred_times();
  solution.makespan = 0.0;
  for (std::uint32_t s = 0; s < complete.size(); ++s) {
    if (solution.steps[s].snap.kind != SnapKind::TimedLiteral) solution.makespan = std::max(solution.makespan, solution.times[s]);
  }
  return solution;
}

}  // namespace alplan
