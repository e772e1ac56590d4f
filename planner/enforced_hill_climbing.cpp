#include <algorithm>
#include <deque>

#include "planner/search_engine.h"

namespace alplan {
namespace {

bool is_helpful(const SearchNode& parent, const StepRecord& step) {
  return std::find(parent.helpful.begin(), parent.helpful.end(), step.snap) != parent.helpful.end();
}

class EnforcedHillClimbing : public SearchEngine {
 public:
  EnforcedHillClimbing(SearchSpace& space, Heuristic& heuristic, EhcOptions options)
      : space_(space), heuristic_(heuristic), options_(options) {}

  std::string name() const override { return options_.helpful_only ? "ehc (helpful actions)" : "ehc"; }

  SearchStatus step() override {
    if (!started_) {
      started_ = true;
      space_.set_root_heuristic(heuristic_, stats_);
      if (space_.node(space_.root()).h == std::numeric_limits<double>::infinity()) return SearchStatus::Exhausted;
      best_h_ = space_.node(space_.root()).h;
      if (reached_goal(space_.root(), space_.partial_plan(space_.root()))) return SearchStatus::Solved;
      open_.push_back(space_.root());
    }
    if (open_.empty()) return SearchStatus::Exhausted;
    const NodeId id = open_.front();
    open_.pop_front();
    ++stats_.expanded;
    const PartialPlan plan = space_.partial_plan(id);
    std::vector<Successor> successors = space_.successors(id, stats_);
    const SearchNode& parent = space_.node(id);
    // Helpful children first; with helpful_only, the others only when the
    // node has no schedulable helpful child at all. The others (and the
    // helpful ones, unless they go shortest first) are scheduled as they are
    // reached: most are never looked at.
    const auto helpful_end = std::stable_partition(successors.begin(), successors.end(),
                                                   [&](const Successor& s) { return is_helpful(parent, s.step); });
    const std::size_t helpful = static_cast<std::size_t>(helpful_end - successors.begin());
    std::vector<std::optional<Child>> scheduled = options_.makespan_first
                                                      ? shortest_first(id, plan, successors, helpful)
                                                      : std::vector<std::optional<Child>>{};
    bool any_helpful = false;
    for (std::size_t i = 0; i < successors.size(); ++i) {
      if (options_.helpful_only && any_helpful && i >= helpful) break;
      if (passed(options_.deadline)) return SearchStatus::InProgress;
      std::optional<Child> child = i < helpful && options_.makespan_first
                                       ? std::move(scheduled[i])
                                       : space_.schedule(id, plan, std::move(successors[i]), stats_);
      if (!child) continue;
      any_helpful = any_helpful || i < helpful;
      if (space_.known(*child, stats_)) continue;
      if (!space_.evaluate(*child, heuristic_, stats_)) continue;
      const double h = child->node.h;
      PartialPlan child_plan = child->plan;
      std::optional<NodeId> stored = space_.insert(std::move(*child), stats_);
      if (!stored) continue;
      if (h < best_h_) {
        best_h_ = h;
        open_.clear();
        open_.push_back(*stored);
        if (reached_goal(*stored, child_plan)) return SearchStatus::Solved;
        return SearchStatus::InProgress;
      }
      if (h == 0 && reached_goal(*stored, child_plan)) return SearchStatus::Solved;
      open_.push_back(*stored);
    }
    return SearchStatus::InProgress;
  }

 private:
  // The first `helpful` successors scheduled, those that cannot be
  // scheduled dropped, the rest by the makespan they give the partial plan
  // (stable: equals keep the order they were generated in).
  std::vector<std::optional<Child>> shortest_first(NodeId id, const PartialPlan& plan,
                                                   std::vector<Successor>& successors, std::size_t helpful) {
    std::vector<Child> children;
    children.reserve(helpful);
    for (std::size_t i = 0; i < helpful; ++i) {
      if (passed(options_.deadline)) break;
      if (std::optional<Child> child = space_.schedule(id, plan, std::move(successors[i]), stats_)) {
        children.push_back(std::move(*child));
      }
    }
    std::stable_sort(children.begin(), children.end(),
                     [](const Child& a, const Child& b) { return a.node.makespan < b.node.makespan; });
    std::vector<std::optional<Child>> ordered(helpful);  // the unscheduled at the back, empty
    for (std::size_t i = 0; i < children.size(); ++i) ordered[i] = std::move(children[i]);
    return ordered;
  }

  bool reached_goal(NodeId id, const PartialPlan& plan) {
    if (space_.node(id).h != 0) return false;
    solution_ = space_.goal_reached(id, plan);
    return solution_.has_value();
  }

  SearchSpace& space_;
  Heuristic& heuristic_;
  EhcOptions options_;
  bool started_ = false;
  double best_h_ = 0;
  std::deque<NodeId> open_;
};

}  // namespace

std::unique_ptr<SearchEngine> make_enforced_hill_climbing(SearchSpace& space, Heuristic& heuristic,
                                                          EhcOptions options) {
  return std::make_unique<EnforcedHillClimbing>(space, heuristic, options);
}

}  // namespace alplan
