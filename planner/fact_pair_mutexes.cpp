#include "planner/fact_pair_mutexes.h"

#include <algorithm>

namespace alplan {
namespace {

void sort_unique(std::vector<FactId>& facts) {
  std::sort(facts.begin(), facts.end());
  facts.erase(std::unique(facts.begin(), facts.end()), facts.end());
}

void append(std::vector<FactId>& into, const std::vector<FactId>& facts) {
  into.insert(into.end(), facts.begin(), facts.end());
}

// A fact added at start and deleted at end (a lock) counts as added and not
// deleted, one deleted at start and added at end as untouched: either way
// the compressed action reaches no fewer pairs than the temporal one.
CompressedAction compress(const GroundAction& action) {
  CompressedAction out;
  append(out.pre, action.at_start.positive);
  append(out.pre, action.over_all.positive);
  for (FactId f : action.at_end.positive) {
    if (std::find(action.start.add.begin(), action.start.add.end(), f) == action.start.add.end()) out.pre.push_back(f);
  }
  append(out.add, action.start.add);
  append(out.add, action.end.add);
  append(out.del, action.start.del);
  append(out.del, action.end.del);
  sort_unique(out.pre);
  sort_unique(out.add);
  sort_unique(out.del);
  std::vector<FactId> del;
  std::set_difference(out.del.begin(), out.del.end(), out.add.begin(), out.add.end(), std::back_inserter(del));
  out.del = std::move(del);
  return out;
}

bool never(const GroundAction& action) {
  return action.at_start.never || action.over_all.never || action.at_end.never;
}

}  // namespace

std::vector<CompressedAction> compress_actions(const GroundTask& task) {
  std::vector<CompressedAction> actions;
  for (const GroundAction& action : task.actions) {
    if (never(action)) continue;
    const CompressedAction base = compress(action);
    actions.push_back(base);
    for (const HappeningEffects* effects : {&action.start, &action.end}) {
      for (const ConditionalEffect& conditional : effects->conditional) {
        if (conditional.condition.never || conditional.add.empty()) continue;
        CompressedAction with = base;
        append(with.pre, conditional.condition.positive);
        append(with.add, conditional.add);
        sort_unique(with.pre);
        sort_unique(with.add);
        std::vector<FactId> del;
        std::set_difference(with.del.begin(), with.del.end(), with.add.begin(), with.add.end(),
                            std::back_inserter(del));
        with.del = std::move(del);
        actions.push_back(std::move(with));
      }
    }
  }
  for (const GroundTimedLiteral& literal : task.timed_literals) {
    CompressedAction til;
    (literal.positive ? til.add : til.del).push_back(literal.fact);
    actions.push_back(std::move(til));
  }
  return actions;
}

FactPairMutexes::FactPairMutexes(const GroundTask& task, const std::vector<FactId>& start,
                                 const FactPairMutexOptions& options)
    : facts_(task.facts.size()) {
  if (!task.axioms.empty()) return;
  actions_ = compress_actions(task);
  std::uint64_t work = 0;
  for (const CompressedAction& action : actions_) work += (action.pre.size() + 1) * std::uint64_t{facts_};
  if (work > options.max_work_per_round) return;
  single_.assign(facts_, 0);
  pairs_.assign(static_cast<std::size_t>(facts_) * facts_, 0);
  for (FactId f : start) {
    single_[f] = 1;
    for (FactId g : start) {
      if (f != g) pairs_[index(f, g)] = 1;
    }
  }
  while (round()) {
    if (options.deadline && std::chrono::steady_clock::now() > *options.deadline) return;
  }
  analysed_ = true;
}

bool FactPairMutexes::applicable(const CompressedAction& action) const {
  for (std::size_t i = 0; i < action.pre.size(); ++i) {
    if (!single_[action.pre[i]]) return false;
    for (std::size_t j = i + 1; j < action.pre.size(); ++j) {
      if (!pairs_[index(action.pre[i], action.pre[j])]) return false;
    }
  }
  return true;
}

bool FactPairMutexes::mark(FactId f, FactId g) {
  if (f == g) {
    if (single_[f]) return false;
    single_[f] = 1;
    return true;
  }
  if (pairs_[index(f, g)]) return false;
  pairs_[index(f, g)] = 1;
  pairs_[index(g, f)] = 1;
  return true;
}

// One pass over the actions: an applicable action adds each of its adds, each
// pair of them, and each add beside every fact it leaves alone that can hold
// together with its whole precondition.
bool FactPairMutexes::round() {
  bool changed = false;
  std::vector<char> touched(facts_, 0);
  for (const CompressedAction& action : actions_) {
    if (!applicable(action)) continue;
    for (std::size_t i = 0; i < action.add.size(); ++i) {
      changed |= mark(action.add[i], action.add[i]);
      for (std::size_t j = i + 1; j < action.add.size(); ++j) changed |= mark(action.add[i], action.add[j]);
    }
    for (FactId f : action.add) touched[f] = 1;
    for (FactId f : action.del) touched[f] = 1;
    for (FactId q = 0; q < facts_; ++q) {
      if (touched[q] || !single_[q]) continue;
      const bool beside_pre = std::all_of(action.pre.begin(), action.pre.end(),
                                          [&](FactId p) { return p == q || pairs_[index(p, q)]; });
      if (!beside_pre) continue;
      for (FactId f : action.add) changed |= mark(f, q);
    }
    for (FactId f : action.add) touched[f] = 0;
    for (FactId f : action.del) touched[f] = 0;
  }
  return changed;
}

}  // namespace alplan
