#include "planner/goal_orders.h"

#include <algorithm>
#include <tuple>

namespace alplan {
namespace {

// Facts some action (at either end, conditionally or not) or timed literal
// deletes: a goal among them may be undone after it holds.
std::vector<char> deletable(const GroundTask& task) {
  std::vector<char> out(task.facts.size(), 0);
  auto mark = [&](const HappeningEffects& effects) {
    for (FactId f : effects.del) out[f] = 1;
    for (const ConditionalEffect& conditional : effects.conditional) {
      for (FactId f : conditional.del) out[f] = 1;
    }
  };
  for (const GroundAction& action : task.actions) {
    mark(action.start);
    mark(action.end);
  }
  for (const GroundTimedLiteral& literal : task.timed_literals) {
    if (!literal.positive) out[literal.fact] = 1;
  }
  return out;
}

bool holds_beside(const FactPairMutexes& mutexes, const CompressedAction& action, FactId fact) {
  return std::all_of(action.pre.begin(), action.pre.end(), [&](FactId p) { return mutexes.reachable(p, fact); });
}

bool adds(const CompressedAction& action, FactId fact) {
  return std::binary_search(action.add.begin(), action.add.end(), fact);
}

struct OrderSearch {
  const FactPairMutexes& mutexes;
  std::vector<FactId> goals;
  std::vector<std::vector<const CompressedAction*>> achievers;  // by goal position
  std::vector<std::vector<std::size_t>> before;                 // goal positions ordered before each goal

  // Whether an achiever of goal `g` can apply in a state holding `later`
  // and leave one holding every goal already known to precede g.
  bool achievable_after(std::size_t g, std::size_t later) const {
    for (const CompressedAction* action : achievers[g]) {
      if (!holds_beside(mutexes, *action, goals[later])) continue;
      const bool keeps_earlier = std::all_of(before[g].begin(), before[g].end(), [&](std::size_t earlier) {
        return earlier == later || adds(*action, goals[earlier]) || holds_beside(mutexes, *action, goals[earlier]);
      });
      if (keeps_earlier) return true;
    }
    return false;
  }

  bool ordered(std::size_t g, std::size_t later) const {
    return std::find(before[later].begin(), before[later].end(), g) != before[later].end();
  }

  // Rounds until no new order: each order found can close an achiever of
  // another goal.
  void run() {
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t g = 0; g < goals.size(); ++g) {
        for (std::size_t later = 0; later < goals.size(); ++later) {
          if (g == later || ordered(g, later) || achievable_after(g, later)) continue;
          before[later].push_back(g);
          changed = true;
        }
      }
    }
  }
};

}  // namespace

GoalOrders::GoalOrders(const GroundTask& task, const std::vector<FactId>& start, const GoalOrderOptions& options) {
  std::vector<char> in_start(task.facts.size(), 0);
  for (FactId f : start) in_start[f] = 1;
  const std::vector<char> deleted = deletable(task);
  std::vector<FactId> goals;
  for (FactId g : task.goal.positive) {
    if (!in_start[g] && !deleted[g]) goals.push_back(g);
  }
  std::sort(goals.begin(), goals.end());
  goals.erase(std::unique(goals.begin(), goals.end()), goals.end());
  if (goals.size() < 2 || goals.size() > options.max_goals) return;
  const FactPairMutexes mutexes(task, start, options.mutexes);
  if (!mutexes.analysed()) return;
  OrderSearch search{mutexes, goals, std::vector<std::vector<const CompressedAction*>>(goals.size()),
                     std::vector<std::vector<std::size_t>>(goals.size())};
  for (const CompressedAction& action : mutexes.actions()) {
    for (std::size_t g = 0; g < goals.size(); ++g) {
      if (adds(action, goals[g])) search.achievers[g].push_back(&action);
    }
  }
  // An unreachable goal makes the task unsolvable, which the heuristic
  // reports; ordering against it would only say the same thing twice.
  for (FactId g : goals) {
    if (!mutexes.reachable(g)) return;
  }
  search.run();
  for (std::size_t later = 0; later < goals.size(); ++later) {
    for (std::size_t g : search.before[later]) orders_.push_back({goals[g], goals[later]});
  }
  if (orders_.empty()) return;
  std::vector<char> ordered(task.facts.size(), 0);
  for (const GoalOrder& order : orders_) ordered[order.before] = ordered[order.after] = 1;
  goals_added_at_end_.resize(task.actions.size());
  for (std::size_t a = 0; a < task.actions.size(); ++a) {
    for (FactId f : task.actions[a].end.add) {
      if (ordered[f]) goals_added_at_end_[a].push_back(f);
    }
  }
  std::sort(orders_.begin(), orders_.end(),
            [](const GoalOrder& a, const GoalOrder& b) { return std::tie(a.after, a.before) < std::tie(b.after, b.before); });
}

std::optional<GoalOrder> GoalOrders::broken_by(const SearchState& state) const {
  std::vector<FactId> pending;
  for (const RunningAction& running : state.running()) {
    const std::vector<FactId>& goals = goals_added_at_end_[running.action];
    pending.insert(pending.end(), goals.begin(), goals.end());
  }
  auto soon = [&](FactId goal) {
    return state.fact(goal) || std::find(pending.begin(), pending.end(), goal) != pending.end();
  };
  for (const GoalOrder& order : orders_) {
    if (soon(order.after) && !soon(order.before)) return order;
  }
  return std::nullopt;
}

}  // namespace alplan
