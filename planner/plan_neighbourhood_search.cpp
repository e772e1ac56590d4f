#include "planner/plan_neighbourhood_search.h"

#include <algorithm>
#include <deque>
#include <unordered_set>
#include <utility>

namespace alplan {
namespace {

bool same_step(const StepRecord& a, const StepRecord& b) {
  return a.snap == b.snap && a.start_step == b.start_step && a.min_duration == b.min_duration &&
         a.max_duration == b.max_duration && a.simultaneous_with == b.simultaneous_with;
}

class PlanNeighbourhoodSearch : public SearchEngine {
 public:
  PlanNeighbourhoodSearch(const TaskIndex& index, const SearchStart& start, double epsilon, Heuristic& heuristic,
                          const Solution& incumbent, NeighbourhoodOptions options)
      : index_(index), start_(start), epsilon_(epsilon), heuristic_(heuristic), incumbent_(incumbent.steps),
        options_(std::move(options)), depth_(std::max(1, options_.depth)) {
    for (const StepRecord& r : incumbent_) {
      if (r.snap.kind != SnapKind::TimedLiteral) actions_.insert(r.snap.index);
    }
  }

  std::string name() const override {
    const char* kind = options_.kind == NeighbourhoodOptions::Kind::Actions ? "actions" : "states";
    return std::string("neighbourhood (") + kind + ", depth " + std::to_string(depth_) + ")";
  }

  std::size_t stored_elsewhere() const override {
    return states_.size() + (explored_ ? explored_->size() : 0) + (searched_ ? searched_->size() : 0);
  }

  SearchStatus step() override {
    switch (stage_) {
      case Stage::Replay: replay(); return SearchStatus::InProgress;
      case Stage::Explore: explore_one(); return SearchStatus::InProgress;
      case Stage::Search: return search_step();
    }
    return SearchStatus::Exhausted;
  }

 private:
  enum class Stage { Replay, Explore, Search };

  // The incumbent's steps again from the start, in a space of their own:
  // their states are the trajectory, and each is explored `depth_` deep.
  void replay() {
    explored_nodes_ = 0;
    explored_ = std::make_unique<SearchSpace>(index_, start_, epsilon_);
    states_.clear();
    neighbourhood_.clear();
    frontier_.clear();
    NodeId at = explored_->root();
    remember(explored_->node(at).state);
    frontier_.push_back({at, 0});
    for (const StepRecord& wanted : incumbent_) {
      std::optional<NodeId> next;
      for (Child& child : explored_->children(at, explored_->partial_plan(at), stats_)) {
        if (!same_step(child.node.step, wanted)) continue;
        const SearchState state = child.node.state;
        next = explored_->insert(std::move(child), stats_);
        if (!next) next = explored_->find(state);
        break;
      }
      // A step the space no longer schedules the same way (its state was
      // met before under another schedule): the trajectory ends here and
      // the restricted search may find no plan, which ends the round.
      if (!next) break;
      at = *next;
      remember(explored_->node(at).state);
      frontier_.push_back({at, 0});
    }
    stage_ = Stage::Explore;
  }

  // One trajectory or neighbourhood node's children join the neighbourhood.
  void explore_one() {
    // The exploration shares the round's budget: its breadth-first layers
    // grow exponentially with the depth.
    if (frontier_.empty() || passed(options_.deadline) || ++explored_nodes_ > round_budget()) {
      start_search();
      return;
    }
    const auto [id, depth] = frontier_.front();
    frontier_.pop_front();
    ++stats_.expanded;
    for (Child& child : explored_->children(id, explored_->partial_plan(id), stats_)) {
      remember(child.node.state);
      if (depth + 1 >= depth_) continue;
      if (std::optional<NodeId> stored = explored_->insert(std::move(child), stats_)) {
        frontier_.push_back({*stored, depth + 1});
      }
    }
  }

  void start_search() {
    explored_.reset();
    frontier_.clear();
    searched_ = std::make_unique<SearchSpace>(index_, start_, epsilon_);
    BestFirstOptions best;
    best.weight = options_.weight;
    best.preferred_queue = false;
    best.makespan_ties = true;
    best.deadline = options_.deadline;
    best.prune = [this](const SearchNode& node) {
      return !inside(node) || (options_.prune && options_.prune(node));
    };
    inner_ = make_best_first_search(*searched_, heuristic_, std::move(best));
    inner_stats_ = {};
    stage_ = Stage::Search;
  }

  SearchStatus search_step() {
    const SearchStatus status = inner_->step();
    const SearchStatistics now = inner_->statistics();
    stats_ += difference(now, inner_stats_);
    inner_stats_ = now;
    if (status == SearchStatus::Solved) {
      solution_ = inner_->solution();
      return status;
    }
    if (status == SearchStatus::InProgress && explored_nodes_ + now.expanded <= round_budget()) return status;
    // Nothing better within this depth: a wider neighbourhood, or the end.
    inner_.reset();
    searched_.reset();
    if (options_.kind == NeighbourhoodOptions::Kind::Actions || depth_ >= options_.max_depth) {
      return SearchStatus::Exhausted;
    }
    depth_ = std::min(options_.max_depth, depth_ * 2);
    stage_ = Stage::Replay;
    return SearchStatus::InProgress;
  }

  std::uint64_t round_budget() const {
    return std::max<std::uint64_t>(1000, options_.expansions_per_step * incumbent_.size());
  }

  static SearchStatistics difference(const SearchStatistics& a, const SearchStatistics& b) {
    return {a.expanded - b.expanded,         a.evaluated - b.evaluated, a.generated - b.generated,
            a.duplicates - b.duplicates,     a.unschedulable - b.unschedulable, a.dead_ends - b.dead_ends};
  }

  // Whether a node is in the neighbourhood: its state is, or (actions) the
  // step that reached it is one of the incumbent's actions or a literal.
  bool inside(const SearchNode& node) const {
    if (neighbourhood_.contains(&node.state)) return true;
    if (options_.kind != NeighbourhoodOptions::Kind::Actions) return false;
    return node.step.snap.kind == SnapKind::TimedLiteral || actions_.contains(node.step.snap.index);
  }

  void remember(const SearchState& state) {
    if (neighbourhood_.contains(&state)) return;
    states_.push_back(state);
    neighbourhood_.insert(&states_.back());
  }

  const TaskIndex& index_;
  const SearchStart& start_;
  double epsilon_;
  Heuristic& heuristic_;
  // Compared by value only: their `continuous` pointers belong to the
  // space that found the plan, gone by now, and are never read.
  std::vector<StepRecord> incumbent_;
  std::unordered_set<std::uint32_t> actions_;
  NeighbourhoodOptions options_;
  int depth_;
  Stage stage_ = Stage::Replay;
  std::unique_ptr<SearchSpace> explored_;
  std::deque<std::pair<NodeId, int>> frontier_;
  std::deque<SearchState> states_;  // a deque: the set points into it
  std::unordered_set<const SearchState*, SearchStateHash, SearchStateEqual> neighbourhood_;
  std::unique_ptr<SearchSpace> searched_;  // declared before the engine that refers to it
  std::unique_ptr<SearchEngine> inner_;
  SearchStatistics inner_stats_;
  std::uint64_t explored_nodes_ = 0;  // this round's, before the search
};

}  // namespace

std::unique_ptr<SearchEngine> make_plan_neighbourhood_search(const TaskIndex& index, const SearchStart& start,
                                                             double epsilon, Heuristic& heuristic,
                                                             const Solution& incumbent,
                                                             NeighbourhoodOptions options) {
  return std::make_unique<PlanNeighbourhoodSearch>(index, start, epsilon, heuristic, incumbent, std::move(options));
}

}  // namespace alplan
