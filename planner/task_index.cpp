#include "planner/task_index.h"

#include <algorithm>
#include <map>

#include "planner/derived_support.h"

namespace alplan {
namespace {

bool mentions_duration(const GroundExpression& e) {
  if (e.kind == GroundExpression::Kind::Duration) return true;
  return std::any_of(e.operands.begin(), e.operands.end(), mentions_duration);
}

void condition_reads(const ConditionSet& c, Footprint& fp) { append_reads(c, fp.reads, fp.reads_values); }

// An over-all condition: held, not read (snap_action.h).
void condition_holds(const ConditionSet& c, Footprint& fp) { append_reads(c, fp.holds, fp.holds_values); }

bool additive(pddl::AssignOperator op) {
  return op == pddl::AssignOperator::Increase || op == pddl::AssignOperator::Decrease;
}

// `skipped`: conditional effects left out, condition and effects.
void effect_footprint(const HappeningEffects& e, Footprint& fp, const std::vector<std::uint32_t>& skipped = {}) {
  std::vector<NumericVarId> other_values;  // written otherwise than additively, unconditionally
  auto numeric = [&](const std::vector<NumericAssignment>& assignments, bool conditional) {
    for (const NumericAssignment& a : assignments) {
      fp.writes_values.push_back(a.variable);
      append_variables(a.value, fp.reads_values);
      (additive(a.assign) && !conditional ? fp.additive_values : other_values).push_back(a.variable);
    }
  };
  fp.writes.insert(fp.writes.end(), e.add.begin(), e.add.end());
  fp.writes.insert(fp.writes.end(), e.del.begin(), e.del.end());
  fp.adds.insert(fp.adds.end(), e.add.begin(), e.add.end());
  fp.dels.insert(fp.dels.end(), e.del.begin(), e.del.end());
  numeric(e.numeric, false);
  for (std::uint32_t k = 0; k < e.conditional.size(); ++k) {
    const ConditionalEffect& c = e.conditional[k];
    if (std::find(skipped.begin(), skipped.end(), k) != skipped.end()) continue;
    condition_reads(c.condition, fp);
    fp.writes.insert(fp.writes.end(), c.add.begin(), c.add.end());
    fp.writes.insert(fp.writes.end(), c.del.begin(), c.del.end());
    // A conditional add is an add whether or not it fires (and nothing
    // where it does not): it commutes with other adds as a plain one does.
    // Counting it as neither kept a zero-duration action whose start adds a
    // fact conditionally and whose end adds it apart from itself, so that
    // the search proved "no plan exists" where VAL accepts a plan (the
    // differential tester's task 4294971080).
    fp.adds.insert(fp.adds.end(), c.add.begin(), c.add.end());
    fp.dels.insert(fp.dels.end(), c.del.begin(), c.del.end());
    numeric(c.numeric, true);
  }
  // A key written two ways is written neither way only.
  auto drop = [](std::vector<std::uint32_t>& from, const std::vector<std::uint32_t>& keys) {
    std::erase_if(from, [&](std::uint32_t k) { return std::find(keys.begin(), keys.end(), k) != keys.end(); });
  };
  const std::vector<FactId> adds = fp.adds, dels = fp.dels;
  drop(fp.adds, dels);
  drop(fp.dels, adds);
  drop(fp.additive_values, other_values);
}

template <typename T>
void unique(std::vector<T>& v);
void finish(Footprint& fp);

// Atoms that are never facts but that a snap's condition names or its
// effects delete (GroundTask::ghosts), under keys after the facts': VAL's
// mutex rule counts them, so they order snaps like facts do.
void add_ghosts(const GroundTask& t, const ConditionSet& condition, const HappeningEffects& effects, Footprint& fp) {
  const std::uint32_t base = t.facts.size();
  auto reads = [&](const ConditionSet& c) {
    for (std::uint32_t g : c.ghost_mentioned) fp.reads.push_back(base + g);
  };
  reads(condition);
  for (std::uint32_t g : effects.ghost_del) {
    fp.writes.push_back(base + g);
    fp.dels.push_back(base + g);
  }
  for (const ConditionalEffect& c : effects.conditional) {
    reads(c.condition);
    for (std::uint32_t g : c.ghost_del) fp.writes.push_back(base + g);
  }
  finish(fp);
}

template <typename T>
void unique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

void finish(Footprint& fp) {
  unique(fp.reads);
  unique(fp.writes);
  unique(fp.reads_values);
  unique(fp.writes_values);
  unique(fp.holds);
  unique(fp.holds_values);
  unique(fp.adds);
  unique(fp.dels);
  unique(fp.additive_values);
  unique(fp.reads_first);
  unique(fp.reads_first_values);
  // What is read is not merely held; what is read is not written one way
  // only (a reader and writer of one key conflicts with any other writer).
  auto drop = [](std::vector<std::uint32_t>& from, const std::vector<std::uint32_t>& keys) {
    std::erase_if(from, [&](std::uint32_t k) { return std::binary_search(keys.begin(), keys.end(), k); });
  };
  drop(fp.holds, fp.reads);
  drop(fp.holds_values, fp.reads_values);
  // Read first is more than held, less than read.
  drop(fp.reads_first, fp.reads);
  drop(fp.reads_first_values, fp.reads_values);
  drop(fp.holds, fp.reads_first);
  drop(fp.holds_values, fp.reads_first_values);
  drop(fp.adds, fp.reads);
  drop(fp.dels, fp.reads);
  drop(fp.additive_values, fp.reads_values);
}

bool effects_mention_duration(const HappeningEffects& e) {
  auto any = [](const std::vector<NumericAssignment>& v) {
    return std::any_of(v.begin(), v.end(), [](const NumericAssignment& a) { return mentions_duration(a.value); });
  };
  if (any(e.numeric)) return true;
  return std::any_of(e.conditional.begin(), e.conditional.end(),
                     [&](const ConditionalEffect& c) { return any(c.numeric); });
}

bool conditions_mention_duration(const ConditionSet& c) {
  return std::any_of(c.numeric.begin(), c.numeric.end(), [](const GroundComparison& cmp) {
    return mentions_duration(cmp.left) || mentions_duration(cmp.right);
  });
}

// A snap reading a derived fact reads every fact and variable of the
// predicates and functions its rules read (derived_support.h says why not
// only those of the planner's own axioms): without this, a writer of one of
// them could be scheduled at the same time as the reader, which VAL rejects.
class DerivedReads {
 public:
  explicit DerivedReads(const GroundTask& task) : task_(task), lifted_(*task.lifted) {
    facts_of_.resize(task.lifted->predicates.size());
    variables_of_.resize(task.lifted->functions.size());
    for (FactId f = 0; f < task.facts.size(); ++f) {
      if (!task.is_derived(f)) facts_of_[task.facts.key(f).head].push_back(f);
    }
    for (NumericVarId v = 0; v < task.numeric.size(); ++v) variables_of_[task.numeric.key(v).head].push_back(v);
  }

  void expand(Footprint& fp) const {
    expand(fp.reads, fp.reads, fp.reads_values);
    expand(fp.holds, fp.holds, fp.holds_values);
    expand(fp.reads_first, fp.reads_first, fp.reads_first_values);
  }

 private:
  void expand(const std::vector<FactId>& derived_from, std::vector<FactId>& facts,
              std::vector<NumericVarId>& values) const {
    std::vector<PredicateId> predicates;
    std::vector<FunctionId> functions;
    for (FactId f : derived_from) {
      if (!task_.is_derived(f)) continue;
      const PredicateId p = task_.facts.key(f).head;
      predicates.insert(predicates.end(), lifted_.predicates(p).begin(), lifted_.predicates(p).end());
      functions.insert(functions.end(), lifted_.functions(p).begin(), lifted_.functions(p).end());
    }
    unique(predicates);
    unique(functions);
    for (PredicateId p : predicates) facts.insert(facts.end(), facts_of_[p].begin(), facts_of_[p].end());
    for (FunctionId f : functions) values.insert(values.end(), variables_of_[f].begin(), variables_of_[f].end());
  }

 private:
  const GroundTask& task_;
  LiftedDerivedReads lifted_;
  std::vector<std::vector<FactId>> facts_of_;
  std::vector<std::vector<NumericVarId>> variables_of_;
};

template <typename T>
bool intersect(const std::vector<T>& a, const std::vector<T>& b) {
  auto i = a.begin();
  auto j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i < *j) {
      ++i;
    } else if (*j < *i) {
      ++j;
    } else {
      return true;
    }
  }
  return false;
}

// A hard PDDL 3 `always` constraint is read in every state the search makes
// (successor_generator.h). The partial order keeps only the orders that
// reads and writes ask for, so a snap that writes what the constraint reads
// reads all of it: such snaps then keep the order in which the search
// checked their states, and the schedule cannot interleave them into a state
// it never checked.
class AlwaysReads {
 public:
  explicit AlwaysReads(const GroundTask& task) {
    for (const GroundConstraint& g : task.pddl3.constraints) {
      if (g.op != ModalOperator::Always || g.preference) continue;
      Footprint f;
      condition_reads(g.requirement, f);
      finish(f);
      if (!f.reads.empty() || !f.reads_values.empty()) reads_.push_back(std::move(f));
    }
  }
  bool empty() const { return reads_.empty(); }

  void expand(Footprint& fp) const {
    bool grown = false;
    for (const Footprint& r : reads_) {
      if (!intersect(fp.writes, r.reads) && !intersect(fp.writes_values, r.reads_values)) continue;
      fp.reads.insert(fp.reads.end(), r.reads.begin(), r.reads.end());
      fp.reads_values.insert(fp.reads_values.end(), r.reads_values.begin(), r.reads_values.end());
      grown = true;
    }
    if (grown) finish(fp);
  }

 private:
  std::vector<Footprint> reads_;
};

}  // namespace

namespace {

using ConditionFootprint = void (*)(const ConditionSet&, Footprint&);

// A durative action's start and end footprints; the conditional effects
// listed in `skipped_*` are left out (they never fire where these are used).
void durative_footprints(const GroundAction& action, ConditionFootprint over_all,
                         const std::vector<std::uint32_t>& skipped_start, const std::vector<std::uint32_t>& skipped_end,
                         Footprint& start, Footprint& end) {
  condition_reads(action.at_start, start);
  over_all(action.over_all, start);
  for (const GroundDurationConstraint& d : action.duration) append_variables(d.value, start.reads_values);
  effect_footprint(action.start, start, skipped_start);
  condition_reads(action.at_end, end);
  over_all(action.over_all, end);
  effect_footprint(action.end, end, skipped_end);
  // Preferences are soft, but VAL's mutex rule counts what they read.
  for (const GroundPreference& p : action.preferences) {
    if (p.time == pddl::TimeSpecifier::AtStart) condition_reads(p.condition, start);
    if (p.time == pddl::TimeSpecifier::AtEnd) condition_reads(p.condition, end);
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
      const bool adds_again = std::any_of(c.add.begin(), c.add.end(), [&](FactId p) {
        return std::binary_search(own.reads.begin(), own.reads.end(), p) && may_add_again(effects, p);
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
      for (std::uint32_t g : c.condition.ghost_mentioned) conditions.reads.push_back(t.facts.size() + g);
    }
    finish(conditions);
    widen(conditions, ConditionSet{}, HappeningEffects{});
    fp.reads_first.insert(fp.reads_first.end(), conditions.reads.begin(), conditions.reads.end());
    fp.reads_first_values.insert(fp.reads_first_values.end(), conditions.reads_values.begin(),
                                 conditions.reads_values.end());
    finish(fp);
  };
  if (!action.durative) {
    if (action.start.conditional.empty()) return;
    Footprint fp;
    condition_reads(action.at_start, fp);
    effect_footprint(action.start, fp, all_conditionals(action.start));
    for (const GroundPreference& p : action.preferences) condition_reads(p.condition, fp);
    finish(fp);
    widen(fp, action.at_start, without(action.start, all_conditionals(action.start)));
    first_reads(action.start, fp);
    quiet.instant.emplace_back(a, std::move(fp));
    return;
  }
  if (action.start.conditional.empty() && action.end.conditional.empty()) return;
  Footprint start, end;
  durative_footprints(action, over_all, all_conditionals(action.start), all_conditionals(action.end), start, end);
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
      durative_footprints(action, over_all, {}, {}, x.start[a], x.end[a]);
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
      condition_reads(action.at_start, x.instant[a]);
      effect_footprint(action.start, x.instant[a]);
      for (const GroundPreference& p : action.preferences) condition_reads(p.condition, x.instant[a]);
      finish(x.instant[a]);
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
    durative_footprints(action, over_all, cross->start, cross->end, cross->start_footprint, cross->end_footprint);
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

