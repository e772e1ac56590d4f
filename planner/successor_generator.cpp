#include "planner/successor_generator.h"

#include <algorithm>
#include <cmath>

#include "planner/formula_evaluation.h"
#include "planner/happening_effects.h"

namespace alplan {
namespace {

bool additive(pddl::AssignOperator op) {
  return op == pddl::AssignOperator::Increase || op == pddl::AssignOperator::Decrease;
}

void narrow(DurationWindow& window, pddl::Comparison comparison, double v) {
  if (comparison != pddl::Comparison::LessEqual) window.min = std::max(window.min, v);
  if (comparison != pddl::Comparison::GreaterEqual) window.max = std::min(window.max, v);
}

// Whether the expression's value can differ between states.
bool reads_state(const GroundExpression& e) {
  using K = GroundExpression::Kind;
  if (e.kind == K::Variable || e.kind == K::Duration || e.kind == K::TotalTime) return true;
  return std::any_of(e.operands.begin(), e.operands.end(), [](const GroundExpression& o) { return reads_state(o); });
}

void settle(DurationWindow& window) {
  window.valid = window.valid && window.min <= window.max + 1e-9 && window.min >= 0.0;
}

}  // namespace

DurationWindow duration_window(const GroundAction& action, Moment moment, const SearchState& state,
                               const ContinuousModel* model) {
  DurationWindow window;
  try {
    for (const GroundDurationConstraint& d : action.duration) {
      if (d.moment != moment) continue;
      if (model && model->changing(d.value)) continue;
      narrow(window, d.comparison, evaluate(d.value, state, EvaluationContext{}));
    }
  } catch (const EvaluationError&) {
    window.valid = false;
  }
  settle(window);
  return window;
}

std::optional<DurationWindow> constant_duration_window(const GroundAction& action, Moment moment) {
  for (const GroundDurationConstraint& d : action.duration) {
    if (d.moment == moment && reads_state(d.value)) return std::nullopt;
  }
  // Undefined static values (satellite's slew times between some directions)
  // throw here once instead of in every evaluation.
  return duration_window(action, moment, SearchState{});
}

bool SuccessorGenerator::apply_effects(const HappeningEffects& effects, const SearchState& before, double duration,
                                       SearchState& after, bool& quiet, const std::vector<std::uint32_t>& skipped) const {
  // VAL's order within a happening: conditions and right-hand sides read the
  // state before; deletes, then adds, then numeric updates.
  EvaluationContext context;
  context.duration = duration;
  quiet = true;
  std::vector<const std::vector<FactId>*> adds{&effects.add}, dels{&effects.del};
  std::vector<const std::vector<NumericAssignment>*> numeric{&effects.numeric};
  try {
    for (std::uint32_t k = 0; k < effects.conditional.size(); ++k) {
      const ConditionalEffect& c = effects.conditional[k];
      if (std::find(skipped.begin(), skipped.end(), k) != skipped.end()) continue;
      if (!holds(c.condition, before, context, 0.0)) continue;
      quiet = false;
      adds.push_back(&c.add);
      dels.push_back(&c.del);
      numeric.push_back(&c.numeric);
    }
    std::vector<std::pair<const NumericAssignment*, double>> updates;
    for (const auto* list : numeric) {
      for (const NumericAssignment& a : *list) updates.emplace_back(&a, evaluate(a.value, before, context));
    }
    // A snap that changes one value twice, not both times additively, is
    // a mutex with itself in VAL (its Ownership.cpp): never applicable.
    for (std::size_t i = 0; i < updates.size(); ++i) {
      for (std::size_t j = i + 1; j < updates.size(); ++j) {
        if (updates[i].first->variable == updates[j].first->variable &&
            !(additive(updates[i].first->assign) && additive(updates[j].first->assign))) {
          return false;
        }
      }
    }
    for (const auto* list : dels) {
      for (FactId f : *list) after.set_fact(f, false);
    }
    for (const auto* list : adds) {
      for (FactId f : *list) after.set_fact(f, true);
    }
    for (const auto& [a, v] : updates) {
      // The executor's operator semantics (an undefined value counts as 0).
      after.set_value(a->variable, updated_value(after.value(a->variable), a->assign, v));
    }
  } catch (const EvaluationError&) {
    return false;
  }
  derive(index_.task(), after);
  return true;
}

bool SuccessorGenerator::condition_holds(const ConditionSet& c, const SearchState& state, double duration) const {
  if (continuous_) return continuous_->holds_fixed_part(c, state, duration);
  EvaluationContext context;
  context.duration = duration;
  try {
    return holds(c, state, context, 0.0);
  } catch (const EvaluationError&) {
    return false;
  }
}

SuccessorGenerator::SuccessorGenerator(const TaskIndex& index, bool self_overlap, bool pending_invariants)
    : index_(index), self_overlap_(self_overlap), pending_invariants_(pending_invariants),
      continuous_(index.continuous().get()) {
  const auto& actions = index.task().actions;
  constant_start_window_.reserve(actions.size());
  for (const GroundAction& a : actions) constant_start_window_.push_back(constant_duration_window(a, Moment::Start));
  for (const GroundConstraint& g : index.task().pddl3.constraints) {
    if (g.op == ModalOperator::Always && !g.preference && !g.requirement.empty()) always_.push_back(&g.requirement);
  }
  givers_at_start_.assign(index.task().facts.size(), {});
  takers_at_start_.assign(index.task().facts.size(), {});
  changers_at_start_.assign(index.task().numeric.size(), {});
  for (ActionId a = 0; a < actions.size(); ++a) {
    auto note = [&](const std::vector<FactId>& add, const std::vector<FactId>& del,
                    const std::vector<NumericAssignment>& numeric) {
      for (FactId f : add) givers_at_start_[f].push_back(a);
      for (FactId f : del) takers_at_start_[f].push_back(a);
      for (const NumericAssignment& n : numeric) changers_at_start_[n.variable].push_back(a);
    };
    note(actions[a].start.add, actions[a].start.del, actions[a].start.numeric);
    for (const ConditionalEffect& c : actions[a].start.conditional) note(c.add, c.del, c.numeric);
  }
}

bool SuccessorGenerator::attach_continuous(const GroundAction& action, const SearchState& before, double duration,
                                           StepRecord& step) const {
  if (!continuous_) return true;
  std::optional<ContinuousStep> part = continuous_->step(action, step.snap.kind, before, duration);
  if (!part) return false;
  if (!part->empty()) step.continuous = &continuous_steps_.emplace_back(std::move(*part));
  return true;
}

bool SuccessorGenerator::invariants_hold(const SearchState& state, bool except_open) const {
  for (const RunningAction& r : state.running()) {
    // A zero-duration action's invariant spans an empty interval: VAL never
    // checks it, and nothing running alongside can break it.
    if (r.max_duration == 0.0 || (except_open && state.joined_open_happening(r))) continue;
    if (!condition_holds(index_.task().actions[r.action].over_all, state, r.min_duration)) return false;
  }
  return always_hold(state);
}

bool SuccessorGenerator::always_hold(const SearchState& state) const {
  for (const ConditionSet* always : always_) {
    if (!condition_holds(*always, state, std::nan(""))) return false;
  }
  return true;
}

bool SuccessorGenerator::settle_invariants(const SearchState& before, ActionId started, Successor& s) const {
  if (before.open_happening() != kNoId) {
    if (!join_open_happening(before, s)) return false;
    if (s.state.open_happening() == kNoId || started == kNoId) return true;
    // A joiner whose own invariant fails needs a member still to come that
    // may give it, as the opener did (only members change the state here).
    for (const RunningAction& r : s.state.running()) {
      if (r.action == started && r.start_step == kStepNotYetKnown &&
          !condition_holds(index_.task().actions[started].over_all, s.state, r.min_duration)) {
        return may_be_given(started, before, s.state);
      }
    }
    return true;
  }
  if (invariants_hold(s.state)) return true;
  if (!pending_invariants_ || started == kNoId || continuous_) return false;
  s.state.open_happening(kStepNotYetKnown, false);
  return invariants_hold(s.state, true) && may_be_given(started, before, s.state);
}

bool SuccessorGenerator::join_open_happening(const SearchState& before, Successor& s) const {
  s.step.simultaneous_with = before.open_happening();
  if (!invariants_hold(s.state, true)) return false;
  if (invariants_hold(s.state)) s.state.close_happening();
  return true;
}

bool SuccessorGenerator::may_be_given(ActionId started, const SearchState& before, const SearchState& after) const {
  // Each part of the invariant that fails needs a start or instantaneous
  // action able to join (its condition holds in the state before the
  // happening, as members of one happening do not interfere) and to change
  // what that part reads. Another run of the started action counts where
  // runs may overlap.
  const GroundTask& task = index_.task();
  const GroundAction& action = task.actions[started];
  auto can_join = [&](const std::vector<ActionId>& candidates) {
    return std::any_of(candidates.begin(), candidates.end(), [&](ActionId g) {
      return (g != started || self_overlap_) && condition_holds(task.actions[g].at_start, before, std::nan(""));
    });
  };
  // A timed literal still to come may join too, where its time is the happening's.
  const auto& literals = task.timed_literals;
  auto literal_sets = [&](FactId f, bool positive) {
    return std::any_of(literals.begin() + before.next_timed_literal(), literals.end(),
                       [&](const GroundTimedLiteral& l) { return l.fact == f && l.positive == positive; });
  };
  auto in = [](const std::vector<FactId>& v, FactId f) { return std::find(v.begin(), v.end(), f) != v.end(); };
  // A derived fact may be given by whatever its rules read: not filtered.
  for (FactId f : action.over_all.positive) {
    if (after.fact(f) || task.is_derived(f)) continue;
    // Its own start deleting it: another member adding it is a mutex.
    if (in(action.start.del, f) || !(can_join(givers_at_start_[f]) || literal_sets(f, true))) return false;
  }
  for (FactId f : action.over_all.negative) {
    if (!after.fact(f) || task.is_derived(f)) continue;
    if (in(action.start.add, f) || !(can_join(takers_at_start_[f]) || literal_sets(f, false))) return false;
  }
  if (action.over_all.numeric.empty() && action.over_all.complex.empty()) return true;
  ConditionSet rest;
  rest.numeric = action.over_all.numeric;
  rest.complex = action.over_all.complex;
  double duration = std::nan("");
  for (const RunningAction& r : after.running()) {
    if (r.action == started && r.start_step == kStepNotYetKnown) duration = r.min_duration;
  }
  if (condition_holds(rest, after, duration)) return true;
  std::vector<FactId> facts;
  std::vector<NumericVarId> variables;
  append_reads(rest, facts, variables);
  const auto changed = [&](NumericVarId v) { return can_join(changers_at_start_[v]); };
  const auto written = [&](FactId f) {
    return can_join(givers_at_start_[f]) || can_join(takers_at_start_[f]) || literal_sets(f, true) ||
           literal_sets(f, false);
  };
  return std::any_of(variables.begin(), variables.end(), changed) || std::any_of(facts.begin(), facts.end(), written);
}

void SuccessorGenerator::add_end(const SearchState& state, std::size_t running_index,
                                 std::vector<Successor>& out) const {
  const RunningAction running = state.running()[running_index];
  const GroundAction& action = index_.task().actions[running.action];
  EvaluationContext context;
  const bool fixed = running.min_duration == running.max_duration;
  context.duration = fixed ? running.min_duration : std::nan("");
  if (!condition_holds(action.at_end, state, context.duration)) return;
  double min = running.min_duration, max = running.max_duration;
  if (!action.duration.empty() && running.start_step != kNoId) {
    const DurationWindow at_end = duration_window(action, Moment::End, state, continuous_);
    if (!at_end.valid) return;
    min = std::max(min, at_end.min);
    max = std::min(max, at_end.max);
    if (min > max + 1e-9) return;
  }
  Successor s{{{SnapKind::End, running.action}, running.start_step, min, max}, state};
  if (!attach_continuous(action, state, context.duration, s.step)) return;
  s.state.finish(running_index);
  // A zero-duration end shares its start's happening: VAL reads its
  // conditional effects' conditions before the start, where the start
  // found those reading its writes false (zero_duration_conditionals_clear).
  const TaskIndex::CrossConditionals* cross = running.max_duration == 0.0 ? index_.cross_conditionals(running.action) : nullptr;
  if (!apply_effects(action.end, state, context.duration, s.state, s.step.quiet,
                     cross ? cross->end : std::vector<std::uint32_t>{})) {
    return;
  }
  if (state.open_happening() != kNoId) s.step.simultaneous_with = state.open_happening();
  if (invariants_hold(s.state)) {
    s.state.close_happening();
  } else {
    // Invariants this end broke: their actions may still end in its
    // happening (generate() offers only their ends), where VAL checks none.
    if (!pending_invariants_ || continuous_ || !always_hold(s.state)) return;
    if (state.open_happening() == kNoId) s.state.open_happening(kStepNotYetKnown, true);
  }
  out.push_back(std::move(s));
}

bool SuccessorGenerator::zero_duration_conditionals_clear(ActionId id, const SearchState& before) const {
  const TaskIndex::CrossConditionals* cross = index_.cross_conditionals(id);
  if (!cross) return true;
  const GroundAction& action = index_.task().actions[id];
  EvaluationContext context;
  context.duration = 0.0;
  try {
    for (const auto& [effects, listed] : {std::pair{&action.start, &cross->start}, std::pair{&action.end, &cross->end}}) {
      for (std::uint32_t k : *listed) {
        if (holds(effects->conditional[k].condition, before, context, 0.0)) return false;
      }
    }
  } catch (const EvaluationError&) {
    return false;
  }
  return true;
}

void SuccessorGenerator::add_timed_literal(const SearchState& state, std::vector<Successor>& out) const {
  const std::uint32_t next = state.next_timed_literal();
  if (next >= index_.task().timed_literals.size()) return;
  const GroundTimedLiteral& til = index_.task().timed_literals[next];
  Successor s{{{SnapKind::TimedLiteral, next}}, state};
  s.state.set_fact(til.fact, til.positive);
  s.state.set_next_timed_literal(next + 1);
  derive(index_.task(), s.state);
  if (state.open_happening() == kNoId) {
    if (invariants_hold(s.state)) out.push_back(std::move(s));
    return;
  }
  // A literal giving the invariant of a start at its own time.
  if (join_open_happening(state, s)) out.push_back(std::move(s));
}

void SuccessorGenerator::add_action(const SearchState& state, ActionId id, std::vector<Successor>& out) const {
  const GroundAction& action = index_.task().actions[id];
  // Conditions on ?duration are checked per duration choice below.
  if (!action.durative) {
    if (!condition_holds(action.at_start, state, std::nan(""))) return;
    Successor s{{{SnapKind::Instant, id}}, state};
    if (!attach_continuous(action, state, std::nan(""), s.step)) return;
    if (apply_effects(action.start, state, std::nan(""), s.state, s.step.quiet) && settle_invariants(state, kNoId, s)) {
      out.push_back(std::move(s));
    }
    return;
  }
  if (state.is_running(id) && (!self_overlap_ || !action.continuous.empty())) return;
  const std::optional<DurationWindow>& constant = constant_start_window_[id];
  const DurationWindow window = constant ? *constant : duration_window(action, Moment::Start, state, continuous_);
  if (!window.valid) return;
  // With effects or conditions on ?duration the duration is fixed at start:
  // the shortest and, when bounded and different, the longest are tried.
  std::vector<std::pair<double, double>> choices;
  if (index_.duration_dependent(id)) {
    choices.emplace_back(window.min, window.min);
    if (window.max < kInfiniteDuration && window.max > window.min + 1e-9) choices.emplace_back(window.max, window.max);
  } else {
    choices.emplace_back(window.min, window.max);
  }
  for (const auto& [min, max] : choices) {
    Successor s{{{SnapKind::Start, id}, kNoId, min, max}, state};
    const double duration = min == max ? min : std::nan("");
    if (!condition_holds(action.at_start, state, duration)) continue;
    if (max == 0.0 && !zero_duration_conditionals_clear(id, state)) continue;
    if (!attach_continuous(action, state, duration, s.step)) continue;
    if (!apply_effects(action.start, state, duration, s.state, s.step.quiet)) continue;
    // The new action's invariant must hold right after its start (or come
    // from a start in its happening: settle_invariants), and so must
    // everyone else's.
    s.state.start({id, kStepNotYetKnown, min, max});
    if (!settle_invariants(state, max > 0.0 ? id : kNoId, s)) continue;
    out.push_back(std::move(s));
  }
}

void SuccessorGenerator::generate(const SearchState& state, std::vector<Successor>& out) const {
  if (state.ends_open()) {
    // Only the ends of the actions whose invariant an end of this happening broke.
    for (std::size_t r = 0; r < state.running().size(); ++r) {
      const RunningAction& run = state.running()[r];
      if (run.max_duration > 0.0 &&
          !condition_holds(index_.task().actions[run.action].over_all, state, run.min_duration)) {
        add_end(state, r, out);
      }
    }
    return;
  }
  // An open happening: only starts, instantaneous actions and timed
  // literals may join it.
  if (state.open_happening() == kNoId) {
    for (std::size_t r = 0; r < state.running().size(); ++r) add_end(state, r, out);
  }
  add_timed_literal(state, out);
  const std::vector<std::uint64_t>& bits = state.bits();
  for (std::size_t word = 0; word < bits.size(); ++word) {
    for (std::uint64_t w = bits[word]; w != 0; w &= w - 1) {
      const FactId f = static_cast<FactId>(word * 64 + static_cast<std::size_t>(__builtin_ctzll(w)));
      for (ActionId a : index_.indexed_by(f)) add_action(state, a, out);
    }
  }
  for (ActionId a : index_.unindexed()) add_action(state, a, out);
}

std::optional<SearchState> SuccessorGenerator::apply(const SearchState& state, const StepRecord& step) const {
  std::vector<Successor> candidates;
  switch (step.snap.kind) {
    case SnapKind::TimedLiteral: add_timed_literal(state, candidates); break;
    case SnapKind::End:
      for (std::size_t r = 0; r < state.running().size(); ++r) {
        if (state.running()[r].action == step.snap.index) add_end(state, r, candidates);
      }
      break;
    default: add_action(state, step.snap.index, candidates); break;
  }
  for (Successor& s : candidates) {
    const bool same_run = step.snap.kind != SnapKind::End || s.step.start_step == step.start_step;
    if (s.step.snap == step.snap && s.step.min_duration == step.min_duration && same_run) return std::move(s.state);
  }
  return std::nullopt;
}

}  // namespace alplan
