#include "planner/task_index.h"

#include <algorithm>
#include <map>

#include "planner/footprint_parts.h"

namespace alplan {
namespace {

using namespace footprint_parts;
using ConditionFootprint = void (*)(const ConditionSet&, Footprint&);

// Preferences are soft, but VAL's mutex rule counts what they read, atoms
// that are never true included (under keys from `ghost_base`, the facts'
// count: task 4294973974, `(preference pp (at start (g0 ?x)))` with
// `(g0 o1)` never true and deleted by another action in the happening).
void preference_reads(const GroundPreference& p, std::uint32_t ghost_base, Footprint& fp) {
  condition_reads(p.condition, fp);
  for (std::uint32_t g : p.condition.ghost_mentioned) fp.reads.push_back(ghost_base + g);
}

// An instantaneous action's footprint; the conditional effects listed in
// `skipped` are left out.
void instant_footprint(const GroundAction& action, std::uint32_t ghost_base, const std::vector<std::uint32_t>& skipped,
                       Footprint& fp) {
  condition_reads(action.at_start, fp);
  effect_footprint(action.start, fp, skipped);
  for (const GroundPreference& p : action.preferences) preference_reads(p, ghost_base, fp);
  finish(fp);
}

// A durative action's start and end footprints; the conditional effects
// listed in `skipped_*` are left out (they never fire where these are used).
void durative_footprints(const GroundAction& action, ConditionFootprint over_all, std::uint32_t ghost_base,
                         const std::vector<std::uint32_t>& skipped_start, const std::vector<std::uint32_t>& skipped_end,
                         Footprint& start, Footprint& end) {
  condition_reads(action.at_start, start);
  over_all(action.over_all, start);
  for (const GroundDurationConstraint& d : action.duration) append_variables(d.value, start.reads_values);
  effect_footprint(action.start, start, skipped_start);
  condition_reads(action.at_end, end);
  over_all(action.over_all, end);
  effect_footprint(action.end, end, skipped_end);
  for (const GroundPreference& p : action.preferences) {
    if (p.time == pddl::TimeSpecifier::AtStart) preference_reads(p, ghost_base, start);
    if (p.time == pddl::TimeSpecifier::AtEnd) preference_reads(p, ghost_base, end);
  }
  // A continuous effect changes its variable from the start to the end:
  // both snaps write it, so readers and writers are ordered around them.
  for (const ContinuousEffect& c : action.continuous) {
    start.writes_values.push_back(c.variable);
    end.writes_values.push_back(c.variable);
    append_variables(c.rate, start.reads_values);
  }
  finish(start);
  finish(end);
}

// The effects without the listed conditional effects.
HappeningEffects without(const HappeningEffects& effects, const std::vector<std::uint32_t>& skipped) {
  HappeningEffects kept = effects;
  kept.conditional.clear();
  for (std::uint32_t k = 0; k < effects.conditional.size(); ++k) {
    if (std::find(skipped.begin(), skipped.end(), k) == skipped.end()) kept.conditional.push_back(effects.conditional[k]);
  }
  return kept;
}

// Whether an event with these effects adds `fact` after it has already
// added or deleted it, in the order VAL constructs effects (adds, deletes,
// then each conditional effect's adds and deletes), taking every
// conditional effect as firing. VAL's Ownership::ownsForAdd refuses such a
// second add of a fact the event read when its happening has other members.
bool may_add_again(const HappeningEffects& e, FactId fact) {
  const auto count = [&](const std::vector<FactId>& v) { return std::count(v.begin(), v.end(), fact); };
  const auto plain_adds = count(e.add) + count(e.added_twice);
  if (plain_adds >= 2) return true;
  auto changes = plain_adds + count(e.del);
  for (const ConditionalEffect& c : e.conditional) {
    if (count(c.add) > 0 && (changes > 0 || count(c.add) > 1)) return true;
    changes += count(c.add) + count(c.del);
  }
  return false;
}

// A snap that may add again a fact it reads must be the only member of its
// happening (see may_add_again): it is given a write of `key`, which every
// snap reads, so the search keeps it epsilon apart from every other snap.
bool must_be_alone(const HappeningEffects& e, const Footprint& fp) {
  auto read_and_added_again = [&](FactId p) {
    return std::binary_search(fp.reads.begin(), fp.reads.end(), p) && may_add_again(e, p);
  };
  if (std::any_of(e.add.begin(), e.add.end(), read_and_added_again)) return true;
  return std::any_of(e.conditional.begin(), e.conditional.end(), [&](const ConditionalEffect& c) {
    return std::any_of(c.add.begin(), c.add.end(), read_and_added_again);
  });
}

// The conditional effects of one snap whose condition reads (widened as the
// footprints are: derived facts, constraints) what the other snap writes,
// or that add again a fact the snap reads (must_be_alone: with its own
// start or end beside it, a zero-duration snap is never alone, so the
// search requires the condition false instead), as
// TaskIndex::CrossConditionals; nothing when there are none.
template <typename Widen>
std::optional<TaskIndex::CrossConditionals> cross_conditionals_of(const GroundAction& action, const Footprint& start,
                                                                   const Footprint& end, const Widen& widen) {
  auto reading = [&](const HappeningEffects& effects, const Footprint& other) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t k = 0; k < effects.conditional.size(); ++k) {
      Footprint read;
      condition_reads(effects.conditional[k].condition, read);
      finish(read);
      widen(read, effects.conditional[k].condition, HappeningEffects{});
      const Footprint& own = &other == &end ? start : end;
      const ConditionalEffect& c = effects.conditional[k];
      // Exact only where the snap changes p unconditionally too (or this
      // effect adds it twice): two conditional adds of p make VAL refuse
      // only when both fire, and are left to must_be_alone (a limit of the
      // proof: search_pipeline.cpp).
      const bool adds_again = std::any_of(c.add.begin(), c.add.end(), [&](FactId p) {
        const auto unconditional = std::count(effects.add.begin(), effects.add.end(), p) +
                                   std::count(effects.del.begin(), effects.del.end(), p) +
                                   std::count(c.add.begin(), c.add.end(), p) - 1;
        return std::binary_search(own.reads.begin(), own.reads.end(), p) && unconditional > 0;
      });
      if (adds_again || intersect(read.reads, other.writes) || intersect(read.reads_values, other.writes_values)) {
        out.push_back(k);
      }
    }
    return out;
  };
  TaskIndex::CrossConditionals cross{reading(action.start, end), reading(action.end, start), {}, {}};
  if (cross.start.empty() && cross.end.empty()) return std::nullopt;
  return cross;
}

std::vector<std::uint32_t> all_conditionals(const HappeningEffects& e) {
  std::vector<std::uint32_t> all(e.conditional.size());
  for (std::uint32_t k = 0; k < all.size(); ++k) all[k] = k;
  return all;
}

// The snaps of an action with conditional effects, footprinted as where
// none fires (TaskIndex::footprint): the effects left out, their
// conditions read first (widened as every footprint is).
template <typename Widen>
void quiet_footprints(const GroundTask& t, ActionId a, ConditionFootprint over_all, const Widen& widen,
                      TaskIndex::QuietFootprints& quiet) {
  const GroundAction& action = t.actions[a];
  auto first_reads = [&](const HappeningEffects& e, Footprint& fp) {
    Footprint conditions;
    for (const ConditionalEffect& c : e.conditional) {
      condition_reads(c.condition, conditions);
      add_ghosts(t, c.condition, HappeningEffects{}, conditions);
    }
    widen(conditions, ConditionSet{}, HappeningEffects{});
    fp.reads_first.insert(fp.reads_first.end(), conditions.reads.begin(), conditions.reads.end());
    fp.reads_first_values.insert(fp.reads_first_values.end(), conditions.reads_values.begin(),
                                 conditions.reads_values.end());
    finish(fp);
  };
  if (!action.durative) {
    if (action.start.conditional.empty()) return;
    Footprint fp;
    instant_footprint(action, t.facts.size(), all_conditionals(action.start), fp);
    widen(fp, action.at_start, without(action.start, all_conditionals(action.start)));
    first_reads(action.start, fp);
    quiet.instant.emplace_back(a, std::move(fp));
    return;
  }
  if (action.start.conditional.empty() && action.end.conditional.empty()) return;
  Footprint start, end;
  durative_footprints(action, over_all, t.facts.size(), all_conditionals(action.start), all_conditionals(action.end),
                      start, end);
  widen(start, action.at_start, without(action.start, all_conditionals(action.start)));
  widen(end, action.at_end, without(action.end, all_conditionals(action.end)));
  first_reads(action.start, start);
  first_reads(action.end, end);
  if (!action.start.conditional.empty()) quiet.start.emplace_back(a, std::move(start));
  if (!action.end.conditional.empty()) quiet.end.emplace_back(a, std::move(end));
}

}  // namespace

std::shared_ptr<const TaskIndex::ActionTables> TaskIndex::index_actions(const GroundTask& t) {
  auto tables = std::make_shared<ActionTables>();
  ActionTables& x = *tables;
  x.by_fact.resize(t.facts.size());
  x.duration_dependent.assign(t.actions.size(), false);
  x.instant.resize(t.actions.size());
  x.start.resize(t.actions.size());
  x.end.resize(t.actions.size());
  std::vector<std::size_t> load(t.facts.size(), 0);
  // With continuous change an invariant's support stays epsilon before its
  // start, as a read: coincident events made the schedule's linear programs
  // degenerate (robot-battery p04 unsolved in 180 s with them, solved in
  // 24 s without, 2026-12-02), and with continuous change an exhausted
  // search is no proof anyway (search_pipeline.h).
  const bool continuous = std::any_of(t.actions.begin(), t.actions.end(),
                                      [](const GroundAction& g) { return !g.continuous.empty(); });
  const auto over_all = continuous ? condition_reads : condition_holds;
  for (ActionId a = 0; a < t.actions.size(); ++a) {
    const GroundAction& action = t.actions[a];
    if (action.durative) {
      durative_footprints(action, over_all, t.facts.size(), {}, {}, x.start[a], x.end[a]);
      x.duration_dependent[a] = effects_mention_duration(action.start) || effects_mention_duration(action.end) ||
                               conditions_mention_duration(action.at_start) ||
                               conditions_mention_duration(action.over_all) ||
                               conditions_mention_duration(action.at_end);
      for (const ConditionalEffect& c : action.end.conditional) {
        if (c.condition_moment == Moment::Start && !x.unsupported) {
          x.unsupported = "the action " + t.action_name(action) +
                         " has an at-end conditional effect whose condition is evaluated at start";
        }
      }
    } else {
      instant_footprint(action, t.facts.size(), {}, x.instant[a]);
    }
    // Index under the least-loaded positive precondition, to spread the lists.
    const std::vector<FactId>& pre = action.at_start.positive;
    if (pre.empty()) {
      x.unindexed.push_back(a);
    } else {
      const FactId f = *std::min_element(pre.begin(), pre.end(),
                                         [&](FactId p, FactId q) { return load[p] < load[q]; });
      ++load[f];
      x.by_fact[f].push_back(a);
    }
  }
  x.continuous = ContinuousModel::build(t);
  if (x.continuous && x.continuous->unsupported() && !x.unsupported) x.unsupported = x.continuous->unsupported();
  const std::optional<DerivedReads> derived = t.axioms.empty() ? std::nullopt : std::optional<DerivedReads>(std::in_place, t);
  const AlwaysReads always(t);
  // What a snap's own conditions and effects do not name but VAL's mutex
  // rule counts: what derived facts are derived from, the constraints its
  // writes touch, atoms that are never facts.
  auto widen = [&](Footprint& fp, const ConditionSet& condition, const HappeningEffects& effects) {
    if (derived) {
      derived->expand(fp);
      finish(fp);
    }
    if (!always.empty()) always.expand(fp);
    if (t.ghosts.size() > 0) add_ghosts(t, condition, effects, fp);
  };
  for (ActionId a = 0; a < t.actions.size(); ++a) {
    const GroundAction& action = t.actions[a];
    if (!action.durative) {
      widen(x.instant[a], action.at_start, action.start);
      continue;
    }
    widen(x.start[a], action.at_start, action.start);
    widen(x.end[a], action.at_end, action.end);
    std::optional<TaskIndex::CrossConditionals> cross = cross_conditionals_of(action, x.start[a], x.end[a], widen);
    if (!cross) continue;
    durative_footprints(action, over_all, t.facts.size(), cross->start, cross->end, cross->start_footprint,
                        cross->end_footprint);
    widen(cross->start_footprint, action.at_start, without(action.start, cross->start));
    widen(cross->end_footprint, action.at_end, without(action.end, cross->end));
    x.cross.emplace_back(a, std::move(*cross));
  }
  for (ActionId a = 0; a < t.actions.size(); ++a) quiet_footprints(t, a, over_all, widen, x.quiet);
  mark_alone_snaps(t, x);
  return tables;
}

void TaskIndex::mark_alone_snaps(const GroundTask& t, ActionTables& x) {
  std::vector<Footprint*> alone;
  for (ActionId a = 0; a < t.actions.size(); ++a) {
    const GroundAction& action = t.actions[a];
    if (!action.durative) {
      if (must_be_alone(action.start, x.instant[a])) alone.push_back(&x.instant[a]);
      continue;
    }
    if (must_be_alone(action.start, x.start[a])) alone.push_back(&x.start[a]);
    if (must_be_alone(action.end, x.end[a])) alone.push_back(&x.end[a]);
  }
  for (auto& [a, cross] : x.cross) {
    if (must_be_alone(without(t.actions[a].start, cross.start), cross.start_footprint)) {
      alone.push_back(&cross.start_footprint);
    }
    if (must_be_alone(without(t.actions[a].end, cross.end), cross.end_footprint)) alone.push_back(&cross.end_footprint);
  }
  for (auto& [a, fp] : x.quiet.instant) {
    if (must_be_alone(without(t.actions[a].start, all_conditionals(t.actions[a].start)), fp)) alone.push_back(&fp);
  }
  for (auto& [a, fp] : x.quiet.start) {
    if (must_be_alone(without(t.actions[a].start, all_conditionals(t.actions[a].start)), fp)) alone.push_back(&fp);
  }
  for (auto& [a, fp] : x.quiet.end) {
    if (must_be_alone(without(t.actions[a].end, all_conditionals(t.actions[a].end)), fp)) alone.push_back(&fp);
  }
  if (alone.empty()) return;
  x.alone_key = alone_key_of(t);
  // Reads stay sorted: the key is above every fact and ghost key.
  auto read = [&](Footprint& fp) { fp.reads.push_back(*x.alone_key); };
  for (std::vector<Footprint>* v : {&x.instant, &x.start, &x.end}) std::for_each(v->begin(), v->end(), read);
  for (auto& [a, cross] : x.cross) {
    read(cross.start_footprint);
    read(cross.end_footprint);
  }
  for (auto* quiet : {&x.quiet.instant, &x.quiet.start, &x.quiet.end}) {
    for (auto& [a, fp] : *quiet) read(fp);
  }
  for (Footprint* fp : alone) fp->writes.push_back(*x.alone_key);
}

std::uint32_t TaskIndex::alone_key_of(const GroundTask& t) {
  return static_cast<std::uint32_t>(t.facts.size() + t.ghosts.size());
}

TaskIndex::TaskIndex(std::shared_ptr<const GroundTask> task) : task_(std::move(task)) {
  actions_ = index_actions(*task_);
  index_rest();
}

TaskIndex::TaskIndex(std::shared_ptr<const GroundTask> task, const TaskIndex& like) : task_(std::move(task)) {
  const bool same = same_ground_actions(*task_, like.task()) &&
                    task_->pddl3.constraints.size() == like.task().pddl3.constraints.size();
  actions_ = same ? like.actions_ : index_actions(*task_);
  index_rest();
}

// What depends on more than the actions: the timed literals, and the
// constructs of the lifted task the planner refuses.
void TaskIndex::index_rest() {
  const GroundTask& t = *task_;
  unsupported_ = actions_->unsupported;
  til_.resize(t.timed_literals.size());
  for (std::size_t i = 0; i < t.timed_literals.size(); ++i) {
    til_[i].writes.push_back(t.timed_literals[i].fact);
    (t.timed_literals[i].positive ? til_[i].adds : til_[i].dels).push_back(t.timed_literals[i].fact);
  }
  if (const AlwaysReads always(t); !always.empty()) {
    for (Footprint& fp : til_) always.expand(fp);
  }
  // A timed literal is a member of its happening as well (VAL).
  if (actions_->alone_key) {
    for (Footprint& fp : til_) fp.reads.push_back(*actions_->alone_key);
  }
  if (!t.lifted->unsupported.empty()) unsupported_ = t.lifted->unsupported.front();
  for (const ActionSchema& schema : t.lifted->actions) {
    if (!schema.unsupported.empty() && !unsupported_) unsupported_ = schema.unsupported;
  }
}

const TaskIndex::CrossConditionals* TaskIndex::cross_conditionals(ActionId action) const {
  const auto& cross = actions_->cross;
  auto it = std::lower_bound(cross.begin(), cross.end(), action,
                             [](const auto& entry, ActionId a) { return entry.first < a; });
  return it != cross.end() && it->first == action ? &it->second : nullptr;
}

const Footprint& TaskIndex::footprint(Snap snap, bool quiet) const {
  if (quiet && snap.kind != SnapKind::TimedLiteral) {
    const auto& list = snap.kind == SnapKind::Instant ? actions_->quiet.instant
                       : snap.kind == SnapKind::Start ? actions_->quiet.start
                                                      : actions_->quiet.end;
    auto it = std::lower_bound(list.begin(), list.end(), snap.index,
                               [](const auto& entry, ActionId a) { return entry.first < a; });
    if (it != list.end() && it->first == snap.index) return it->second;
  }
  return footprint(snap);
}

const Footprint& TaskIndex::footprint(Snap snap) const {
  switch (snap.kind) {
    case SnapKind::Instant: return actions_->instant[snap.index];
    case SnapKind::Start: return actions_->start[snap.index];
    case SnapKind::End: return actions_->end[snap.index];
    case SnapKind::TimedLiteral: return til_[snap.index];
  }
  return actions_->instant[snap.index];
}

}  // namespace alplan

