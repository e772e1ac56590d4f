#include <algorithm>
#include <queue>
#include <sstream>
#include <unordered_map>

#include "planner/search_engine.h"
#include "planner/novelty_table.h"
#include "planner/type_bucket_queue.h"

namespace alplan {
namespace {

struct Entry {
  double f;
  double h;
  // The node's makespan bound with BestFirstOptions::makespan_ties, else 0.
  double makespan;
  std::uint64_t order;  // first in, first out among equals
  NodeId node;
  bool operator>(const Entry& o) const {
    if (f != o.f) return f > o.f;
    if (h != o.h) return h > o.h;
    if (makespan != o.makespan) return makespan > o.makespan;
    return order > o.order;
  }
};
using OpenList = std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>>;

class BestFirstSearch : public SearchEngine {
 public:
  BestFirstSearch(SearchSpace& space, Heuristic& heuristic, BestFirstOptions options)
      : space_(space), heuristic_(heuristic), options_(std::move(options)),
        // Ordered by the metric, a goal must be known when it is queued.
        deferred_(options_.deferred && !by_metric()),
        // Ordered by the metric, a node drawn at random could end the search
        // with a plan the main queue would have ranked behind a cheaper one.
        type_exploration_(options_.type_exploration && !by_metric() && !options_.complete),
        novelty_(options_.novelty && options_.weight == 0),
        novelties_(options_.novelty_width),
        types_(options_.seed) {}

  std::string name() const override {
    std::string traits;  // ", deferred, type-based"
    if (deferred_) traits += ", deferred";
    if (type_exploration_) traits += ", type-based";
    if (novelty_) traits += ", novelty";
    if (options_.complete) traits += ", complete";
    if (options_.makespan_ties) traits += ", makespan ties";
    if (options_.weight == 0) return traits.empty() ? "gbfs" : "gbfs (" + traits.substr(2) + ")";
    std::ostringstream weight;  // 3, not 3.000000
    weight << options_.weight;
    return "wastar (w=" + weight.str() + (options_.metric ? ", metric" : "") + traits + ")";
  }

  SearchStatus step() override {
    if (!started_) {
      started_ = true;
      space_.set_root_heuristic(heuristic_, stats_);
      const SearchNode& root = space_.node(space_.root());
      if (root.h == std::numeric_limits<double>::infinity()) return SearchStatus::Exhausted;
      if ((root.h == 0 || options_.complete) &&
          (solution_ = space_.goal_reached(space_.root(), space_.partial_plan(space_.root())))) {
        return SearchStatus::Solved;
      }
      push(space_.root(), false);
    }
    std::optional<NodeId> id = pop();
    if (!id) return SearchStatus::Exhausted;
    if (auto goal = goals_.find(*id); goal != goals_.end()) {
      solution_ = std::move(goal->second);
      return SearchStatus::Solved;
    }
    const PartialPlan plan = space_.partial_plan(*id);
    if (!space_.node(*id).evaluated) {
      // Deferred: the node waited in the queue under its parent's h.
      if (!space_.evaluate_stored(*id, plan, heuristic_, stats_)) return SearchStatus::InProgress;
      const SearchNode& n = space_.node(*id);
      if (options_.prune && options_.prune(n)) return SearchStatus::InProgress;
      if ((n.h == 0 || options_.complete) && (solution_ = space_.goal_reached(*id, plan))) return SearchStatus::Solved;
    }
    ++stats_.expanded;
    std::vector<Child> children = space_.children(*id, plan, stats_);
    return deferred_ ? store_unevaluated(*id, children) : store_evaluated(*id, children);
  }

 private:
  bool preferred(NodeId parent, const Child& child) const {
    const std::vector<Snap>& helpful = space_.node(parent).helpful;
    return std::find(helpful.begin(), helpful.end(), child.node.step.snap) != helpful.end();
  }

  SearchStatus store_evaluated(NodeId parent, std::vector<Child>& children) {
    for (Child& child : children) {
      if (options_.prune && options_.prune(child.node)) continue;
      if (passed(options_.deadline)) return SearchStatus::InProgress;
      const bool is_preferred = preferred(parent, child);
      if (space_.known(child, stats_)) continue;
      if (!space_.evaluate(child, heuristic_, stats_)) continue;
      if (options_.prune && options_.prune(child.node)) continue;
      PartialPlan child_plan = child.plan;
      std::optional<NodeId> stored = space_.insert(std::move(child), stats_);
      if (!stored) continue;
      if (space_.node(*stored).h == 0 || options_.complete) {
        if (std::optional<Solution> goal = space_.goal_reached(*stored, child_plan)) {
          if (!by_metric()) {
            solution_ = std::move(goal);
            return SearchStatus::Solved;
          }
          // Ordered by the metric, a goal is a solution when it leaves the
          // main open list (A*'s test at expansion): one found at generation
          // may cost more than a plan through a node still open. Not from
          // the helpful queue, which would hand it out whatever its f.
          goals_.emplace(*stored, std::move(*goal));
          push(*stored, false);
          continue;
        }
      }
      push(*stored, is_preferred);
    }
    return SearchStatus::InProgress;
  }

  // Deferred evaluation (Richter & Helmert, ICAPS 2009): children are
  // queued under their parent's h and evaluated only when taken out, so a
  // node pays for one evaluation instead of one per child; with preferred
  // operators the helpful children still go first.
  SearchStatus store_unevaluated(NodeId parent, std::vector<Child>& children) {
    const double h = space_.node(parent).h;
    for (Child& child : children) {
      if (passed(options_.deadline)) return SearchStatus::InProgress;
      child.node.h = h;
      child.node.makespan_bound = child.node.makespan;
      if (options_.prune && options_.prune(child.node)) continue;
      const bool is_preferred = preferred(parent, child);
      if (std::optional<NodeId> stored = space_.insert(std::move(child), stats_)) push(*stored, is_preferred);
    }
    return SearchStatus::InProgress;
  }

  bool by_metric() const { return options_.weight != 0 && options_.metric; }

  void push(NodeId id, bool preferred) {
    const SearchNode& n = space_.node(id);
    // Metric and step counts are never mixed in f: their units differ (a
    // cost of 1000 against 3 steps), so any sum would let one drown the other.
    double f = n.h;
    if (by_metric()) {
      f = options_.metric->value(n.state, n.makespan) +
          options_.weight * options_.metric->remaining(n.relaxed_cost, n.makespan, n.makespan_bound);
    } else if (options_.weight != 0) {
      f = n.depth + options_.weight * n.h;
    } else if (novelty_ && n.h != std::numeric_limits<double>::infinity()) {
      f = novelties_.novelty(n.h, n.state);
    }
    const Entry entry{f, n.h, options_.makespan_ties ? n.makespan_bound : 0.0, order_++, id};
    open_.push(entry);
    if (preferred && options_.preferred_queue) preferred_.push(entry);
    if (type_exploration_ && n.h != std::numeric_limits<double>::infinity()) types_.push(n.h, n.depth, id);
  }

  enum class Queue { Preferred, Open, Types };

  // The helpful queue twice for every turn of the main one (and of the
  // type-based one, when there is one); an empty queue passes its turn on.
  std::optional<NodeId> take(Queue queue) {
    if (queue == Queue::Types) return types_.pop();
    OpenList& q = queue == Queue::Preferred ? preferred_ : open_;
    if (q.empty()) return std::nullopt;
    const NodeId id = q.top().node;
    q.pop();
    return id;
  }

  std::optional<NodeId> next_from_some_queue() {
    static constexpr Queue kTurns[] = {Queue::Preferred, Queue::Preferred, Queue::Open, Queue::Types};
    const std::size_t turns = type_exploration_ ? 4 : 3;
    for (std::size_t k = 0; k < turns; ++k) {
      if (std::optional<NodeId> id = take(kTurns[(turn_ + k) % turns])) {
        turn_ += k + 1;
        return id;
      }
    }
    return std::nullopt;
  }

  std::optional<NodeId> pop() {
    // A node may sit in several queues and is expanded once.
    while (std::optional<NodeId> id = next_from_some_queue()) {
      if (expanded_.size() <= *id) expanded_.resize(*id + 1, false);
      if (expanded_[*id]) continue;
      expanded_[*id] = true;
      return id;
    }
    return std::nullopt;
  }

  SearchSpace& space_;
  Heuristic& heuristic_;
  BestFirstOptions options_;
  bool deferred_;
  bool type_exploration_;
  bool novelty_;
  NoveltyTable novelties_;
  bool started_ = false;
  OpenList open_, preferred_;
  TypeBucketQueue types_;
  std::vector<bool> expanded_;
  std::unordered_map<NodeId, Solution> goals_;  // goals generated, not yet popped (metric order)
  std::uint64_t order_ = 0;
  std::uint64_t turn_ = 0;
};

}  // namespace

std::unique_ptr<SearchEngine> make_best_first_search(SearchSpace& space, Heuristic& heuristic,
                                                     BestFirstOptions options) {
  return std::make_unique<BestFirstSearch>(space, heuristic, std::move(options));
}

}  // namespace alplan
