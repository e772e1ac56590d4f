#include "oracle/judge.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>

#include "oracle/derived.h"
#include "oracle/effects.h"
#include "oracle/evaluate.h"
#include "oracle/ownership.h"
#include "oracle/reads.h"
#include "oracle/trajectory.h"
#include "pddl_parser/writer.h"

namespace alplan::oracle {
namespace {

// VAL's fixed slack on comparisons outside invariants (Comparison::
// evaluateAtPointError), whatever -t is.
constexpr double kValSlack = 0.0001;

enum class MemberKind : unsigned char { Instant, Start, End, Til };

struct Member {
  MemberKind kind = MemberKind::Instant;
  int index = 0;  // the step, or the timed literal
  double time = 0.0;
};

struct Happening {
  double time = 0.0;
  std::vector<Member> members;
  bool after_plan = false;  // later than every step's start and end
};

struct ResolvedStep {
  const TimedStep* step = nullptr;
  const ActionParts* parts = nullptr;
  Binding binding;
  double duration = 0.0;
  std::string text;
};

std::string number(double x) { return pddl::format_number(x); }

}  // namespace

const char* to_string(Failure f) {
  switch (f) {
    case Failure::None: return "valid";
    case Failure::BadPlan: return "bad_plan";
    case Failure::Duration: return "duration";
    case Failure::Precondition: return "precondition";
    case Failure::Mutex: return "mutex";
    case Failure::Invariant: return "invariant";
    case Failure::Constraint: return "constraint";
    case Failure::Goal: return "goal";
    case Failure::NotJudged: return "not_judged";
  }
  return "?";
}

class Judge::Run {
 public:
  Run(Judge& judge, const TimedPlan& plan)
      : j_(judge), world_(judge.world_), plan_(plan),
        conditions_{judge.options_.exact ? 0.0 : kValSlack},
        monitor_(judge.world_, conditions_) {}

  Verdict run() {
    try {
      if (!resolve()) return verdict_;
      build_happenings();
      execute();
    } catch (const UndefinedValue& e) {
      fail(Failure::NotJudged, e.what(), verdict_.time);
    } catch (const NotJudged& e) {
      fail(Failure::NotJudged, e.what(), verdict_.time);
    }
    return verdict_;
  }

 private:
  bool fail(Failure f, const std::string& reason, double time) {
    verdict_.failure = f;
    verdict_.reason = reason;
    verdict_.time = time;
    return false;
  }

  bool resolve();
  void build_happenings();
  void execute();
  State initial_state();
  bool conditions_hold(const Member& m, const State& before);
  bool claim_reads(const Member& m, int id, Ownership& ownership);
  bool record_effects(const Member& m, int id, const State& before, Ownership& ownership, bool claim_reads,
                      double time, HappeningChanges& changes);
  bool invariants_hold(const State& after, double time, double next);
  bool separated(const Happening& h, Ownership& claims, double time);
  bool finish(const State& final_state, const State* frozen, double frozen_time);
  std::string member_text(const Member& m) const;

  Judge& j_;
  World& world_;
  const TimedPlan& plan_;
  Comparisons conditions_;
  TrajectoryMonitor monitor_;
  Verdict verdict_;
  std::vector<ResolvedStep> steps_;
  std::vector<Happening> happenings_;
  std::map<std::string, double> counts_;  // preference violations counted in formulas
  std::set<int> running_;                 // steps between their start and their end
  // Per step, the over-all preference instances already counted violated.
  std::map<int, std::set<std::string>> invariant_preferences_violated_;
  std::map<int, std::map<const pddl::Effect*, bool>> decided_;  // deferred conditional effects, by step
  // Under the epsilon-separated rule: the happenings of the last epsilon,
  // with what their members claimed and their texts.
  struct RecentHappening {
    double time = 0.0;
    Ownership claims;
    std::vector<std::string> members;
  };
  std::deque<RecentHappening> recent_;
};

bool Judge::Run::resolve() {
  for (const TimedStep& step : plan_.steps) {
    ResolvedStep r;
    r.step = &step;
    r.text = "(" + step.action;
    for (const std::string& a : step.args) r.text += " " + a;
    r.text += ")";
    const pddl::Action* instant = world_.action(step.action);
    const pddl::DurativeAction* durative = world_.durative_action(step.action);
    if (!instant && !durative) return fail(Failure::BadPlan, "line " + std::to_string(step.line) + ": no action " + step.action, step.time);
    const std::vector<pddl::TypedName>& parameters = instant ? instant->parameters : durative->parameters;
    if (parameters.size() != step.args.size()) {
      return fail(Failure::BadPlan, r.text + " has " + std::to_string(step.args.size()) + " arguments, the action " +
                                        std::to_string(parameters.size()), step.time);
    }
    for (std::size_t k = 0; k < parameters.size(); ++k) {
      if (!world_.is_object(step.args[k]) || !world_.object_fits(step.args[k], parameters[k].types)) {
        return fail(Failure::BadPlan, r.text + ": " + step.args[k] + " is no object of the parameter's type", step.time);
      }
      r.binding.push(parameters[k].name, step.args[k]);
    }
    if (durative) {
      if (!step.duration) return fail(Failure::BadPlan, r.text + " is durative and has no duration", step.time);
      r.duration = *step.duration;
    }
    r.parts = &j_.parts(step.action);
    steps_.push_back(std::move(r));
  }
  return true;
}

void Judge::Run::build_happenings() {
  std::vector<Member> members;
  double last_action = 0.0;
  bool any_action = false;
  for (std::size_t k = 0; k < steps_.size(); ++k) {
    const int i = static_cast<int>(k);
    const double t = steps_[k].step->time;
    const double latest = steps_[k].parts->durative ? std::max(t, t + steps_[k].duration) : t;
    if (steps_[k].parts->durative) {
      members.push_back({MemberKind::Start, i, t});
      members.push_back({MemberKind::End, i, t + steps_[k].duration});
    } else {
      members.push_back({MemberKind::Instant, i, t});
    }
    last_action = any_action ? std::max(last_action, latest) : latest;
    any_action = true;
  }
  const auto& tils = world_.problem().timed_literals;
  for (std::size_t k = 0; k < tils.size(); ++k) members.push_back({MemberKind::Til, static_cast<int>(k), tils[k].time});
  std::stable_sort(members.begin(), members.end(), [](const Member& a, const Member& b) { return a.time < b.time; });
  const double window = j_.options_.tolerance / 10.0;
  for (const Member& m : members) {
    if (happenings_.empty() || m.time > happenings_.back().time + window) happenings_.push_back({m.time, {}, false});
    happenings_.back().members.push_back(m);
  }
  // With no step, every happening is a timed literal after the plan: the
  // value is the initial state's, at time 0 (VAL reads an undefined bound
  // here and measures after the first literal; see the README).
  for (Happening& h : happenings_) h.after_plan = !any_action || h.time > last_action;
  verdict_.makespan = any_action ? last_action : 0.0;
}

State Judge::Run::initial_state() {
  State s;
  for (const pddl::Atom& a : world_.problem().init) {
    if (world_.is_derived(a.name)) continue;  // a derived atom follows from its rules, as VAL has it
    Binding none;
    s.set(world_.atoms().id(ground(a, none)), true);
  }
  for (const pddl::NumericFact& f : world_.problem().numeric_init) {
    Binding none;
    s.assign(world_.fluents().id(ground(f.function, none)), f.value);
  }
  close_derived(world_, s, conditions_);
  return s;
}

std::string Judge::Run::member_text(const Member& m) const {
  switch (m.kind) {
    case MemberKind::Instant: return steps_[static_cast<std::size_t>(m.index)].text;
    case MemberKind::Start: return steps_[static_cast<std::size_t>(m.index)].text + " start";
    case MemberKind::End: return steps_[static_cast<std::size_t>(m.index)].text + " end";
    case MemberKind::Til: {
      const pddl::TimedInitialLiteral& til = world_.problem().timed_literals[static_cast<std::size_t>(m.index)];
      return "the timed literal " + std::string(til.positive ? "" : "(not ") + pddl::write_atom(til.atom) +
             (til.positive ? "" : ")") + " at " + number(til.time);
    }
  }
  return "";
}

bool Judge::Run::conditions_hold(const Member& m, const State& before) {
  if (m.kind == MemberKind::Til) return true;
  ResolvedStep& step = steps_[static_cast<std::size_t>(m.index)];
  const ActionPart& part = m.kind == MemberKind::Instant ? step.parts->instant
                           : m.kind == MemberKind::Start ? step.parts->start
                                                         : step.parts->end;
  Scope scope(world_, before, step.binding, conditions_);
  scope.duration = step.duration;
  scope.preference_counts = &counts_;
  for (const pddl::DurationConstraint& d : part.durations) {
    const double want = value(d.value, scope);
    const double tolerance = j_.options_.tolerance;
    const double dur = step.duration;
    bool ok = false;
    switch (d.comparison) {
      case pddl::Comparison::Equal: ok = std::fabs(dur - want) < tolerance; break;
      case pddl::Comparison::LessEqual: ok = dur - want <= tolerance; break;
      case pddl::Comparison::GreaterEqual: ok = want - dur <= tolerance; break;
      case pddl::Comparison::Less: ok = dur < want; break;
      case pddl::Comparison::Greater: ok = dur > want; break;
    }
    if (!ok) {
      return fail(Failure::Duration, member_text(m) + ": the duration " + number(dur) + " is not " +
                                         pddl::to_string(d.comparison) + " " + number(want), m.time);
    }
  }
  for (const pddl::Condition& c : part.conditions) {
    if (!holds(c, scope)) {
      return fail(Failure::Precondition, member_text(m) + ": " + pddl::write_condition(c) + " does not hold at " +
                                             number(m.time), m.time);
    }
  }
  if (m.kind == MemberKind::Start) {
    for (const DeferredWhen& w : step.parts->deferred) {
      bool fires = !w.at_start || holds(*w.at_start, scope);
      decided_[m.index][w.node] = fires;
    }
  }
  return true;
}

bool Judge::Run::claim_reads(const Member& m, int id, Ownership& ownership) {
  if (m.kind == MemberKind::Til) return true;
  ResolvedStep& step = steps_[static_cast<std::size_t>(m.index)];
  const ActionPart& part = m.kind == MemberKind::Instant ? step.parts->instant
                           : m.kind == MemberKind::Start ? step.parts->start
                                                         : step.parts->end;
  ReadClaims claims(world_, ownership, id);
  bool ok = true;
  for (const pddl::DurationConstraint& d : part.durations) ok = ok && claims.expression(d.value, step.binding);
  for (const pddl::Condition& c : part.conditions) ok = ok && claims.formula(c, step.binding);
  if (m.kind == MemberKind::Start) {
    for (const DeferredWhen& w : step.parts->deferred) {
      if (w.at_start) ok = ok && claims.formula(*w.at_start, step.binding);
    }
  }
  if (!ok) return fail(Failure::Mutex, member_text(m) + " reads " + claims.refused() + ", which another member of the happening at " + number(m.time) + " changes", m.time);
  return true;
}

bool Judge::Run::record_effects(const Member& m, int id, const State& before, Ownership& ownership,
                                bool claim_reads, double time, HappeningChanges& changes) {
  if (m.kind == MemberKind::Til) {
    const pddl::TimedInitialLiteral& til = world_.problem().timed_literals[static_cast<std::size_t>(m.index)];
    Binding none;
    const int atom = world_.atoms().id(ground(til.atom, none));
    const bool ok = til.positive ? ownership.add_fact(id, atom) : ownership.delete_fact(id, atom);
    (til.positive ? changes.adds : changes.deletes).push_back(atom);
    if (!ok) return fail(Failure::Mutex, member_text(m) + " interferes with another member of its happening", time);
    return true;
  }
  ResolvedStep& step = steps_[static_cast<std::size_t>(m.index)];
  const Moment moment = m.kind == MemberKind::Instant ? Moment::Instant
                        : m.kind == MemberKind::Start ? Moment::Start
                                                      : Moment::End;
  const ActionPart& part = moment == Moment::Instant ? step.parts->instant
                           : moment == Moment::Start ? step.parts->start
                                                     : step.parts->end;
  auto decided = decided_.find(m.index);
  EffectRecorder::Context context{world_, before, ownership, id, claim_reads, conditions_, step.duration, time,
                                  moment == Moment::End && decided != decided_.end() ? &decided->second : nullptr};
  EffectRecorder recorder(context, changes);
  if (!recorder.record(part.effects, moment, step.binding)) {
    return fail(Failure::Mutex, member_text(m) + " " + recorder.refused() + ", which interferes with another member of the happening at " + number(time), time);
  }
  return true;
}

bool Judge::Run::invariants_hold(const State& after, double time, double next) {
  const Comparisons exact{0.0};
  for (int k : running_) {
    ResolvedStep& step = steps_[static_cast<std::size_t>(k)];
    Scope scope(world_, after, step.binding, exact);
    scope.duration = step.duration;
    std::map<std::string, std::string> violated;  // preference instance -> name
    scope.preference_instances = &violated;
    for (const pddl::Condition& c : step.parts->invariant) {
      if (!holds(c, scope)) {
        return fail(Failure::Invariant, step.text + ": the over-all condition " + pddl::write_condition(c) +
                                            " fails between " + number(time) + " and " + number(next), time);
      }
    }
    for (const auto& [instance, name] : violated) {
      if (invariant_preferences_violated_[k].insert(instance).second) counts_[name] += 1.0;
    }
    auto decided = decided_.find(k);
    for (const DeferredWhen& w : step.parts->deferred) {
      if (w.over_all && decided != decided_.end() && !holds(*w.over_all, scope)) decided->second[w.node] = false;
    }
  }
  return true;
}

bool Judge::Run::separated(const Happening& h, Ownership& claims, double time) {
  // Within a relative 1e-9 of epsilon is epsilon: a planner's times are
  // sums of epsilons and durations written with a few decimals.
  const double epsilon = j_.options_.epsilon_separation * (1.0 - 1e-9);
  while (!recent_.empty() && time - recent_.front().time >= epsilon) recent_.pop_front();
  for (const RecentHappening& r : recent_) {
    if (r.time >= time) continue;
    if (const std::optional<Ownership::Conflict> c = claims.conflict_with_earlier(r.claims)) {
      const std::string key = c->fluent ? to_string(world_.fluents().name(c->key)) : to_string(world_.atoms().name(c->key));
      return fail(Failure::Mutex,
                  r.members[static_cast<std::size_t>(c->first)] + " at " + number(r.time) + " and " +
                      member_text(h.members[static_cast<std::size_t>(c->second)]) + " at " + number(time) +
                      " both touch " + key + ", one writing it, closer than epsilon (the epsilon-separated rule)",
                  time);
    }
  }
  RecentHappening mine{time, std::move(claims), {}};
  for (const Member& m : h.members) mine.members.push_back(member_text(m));
  recent_.push_back(std::move(mine));
  return true;
}

void Judge::Run::execute() {
  State state = initial_state();
  double now = 0.0;
  std::optional<State> frozen;
  double frozen_time = 0.0;
  if (!happenings_.empty() && happenings_.front().after_plan) frozen = state;
  for (std::size_t i = 0; i < happenings_.size(); ++i) {
    const Happening& h = happenings_[i];
    if (!monitor_.observe(state, now)) return void(fail(Failure::Constraint, monitor_.reason(), now));
    for (const Member& m : h.members) {
      if (!conditions_hold(m, state)) return;
    }
    now = h.time;
    Ownership ownership;
    const bool several = h.members.size() > 1;
    if (several) {
      for (std::size_t k = 0; k < h.members.size(); ++k) {
        if (!claim_reads(h.members[k], static_cast<int>(k), ownership)) return;
      }
    }
    HappeningChanges changes;
    for (std::size_t k = 0; k < h.members.size(); ++k) {
      if (!record_effects(h.members[k], static_cast<int>(k), state, ownership, several, now, changes)) return;
    }
    if (j_.options_.symmetric_mutex && several) {
      if (const std::optional<Ownership::Conflict> c = ownership.symmetric_conflict()) {
        const std::string key = c->fluent ? to_string(world_.fluents().name(c->key)) : to_string(world_.atoms().name(c->key));
        return void(fail(Failure::Mutex,
                         member_text(h.members[static_cast<std::size_t>(c->first)]) + " and " +
                             member_text(h.members[static_cast<std::size_t>(c->second)]) + " both touch " + key +
                             ", one writing it, at " + number(now) + " (the symmetric rule)",
                         now));
      }
    }
    if (j_.options_.epsilon_separation > 0.0) {
      // A lone member's reads were not claimed (nothing to interfere with
      // inside its happening); a happening just before may.
      if (!several && !h.members.empty() && !claim_reads(h.members.front(), 0, ownership)) return;
      if (!separated(h, ownership, now)) return;
    }
    changes.apply_to(state);
    close_derived(world_, state, conditions_);
    for (const Member& m : h.members) {
      if (m.kind == MemberKind::Start) running_.insert(m.index);
    }
    for (const Member& m : h.members) {
      if (m.kind == MemberKind::End) running_.erase(m.index);
    }
    if (i + 1 == happenings_.size()) break;
    const double next = happenings_[i + 1].time;
    if (std::any_of(running_.begin(), running_.end(), [&](int k) {
          const ActionParts& p = *steps_[static_cast<std::size_t>(k)].parts;
          return !p.invariant.empty() || !p.deferred.empty();
        })) {
      if (!monitor_.observe(state, now)) return void(fail(Failure::Constraint, monitor_.reason(), now));
      if (!invariants_hold(state, now, next)) return;
      now = next;
    }
    if (!frozen && happenings_[i + 1].after_plan) {
      frozen = state;
      frozen_time = h.time;
    }
  }
  finish(state, frozen ? &*frozen : nullptr, frozen_time);
}

bool Judge::Run::finish(const State& final_state, const State* frozen, double frozen_time) {
  const double end_time = happenings_.empty() ? 0.0 : happenings_.back().time;
  if (!j_.options_.check_goal) return true;
  if (world_.problem().goal) {
    Binding none;
    Scope scope(world_, final_state, none, conditions_);
    scope.preference_counts = &counts_;
    if (!holds(*world_.problem().goal, scope)) return fail(Failure::Goal, "the goal does not hold at the end", end_time);
  }
  if (!monitor_.observe(final_state, end_time) || !monitor_.finish(final_state)) {
    return fail(Failure::Constraint, monitor_.reason(), end_time);
  }
  std::map<std::string, double> violations = counts_;
  monitor_.add_violations(violations);
  verdict_.preference_violations = violations;
  const double steps = static_cast<double>(plan_.steps.size() + world_.problem().timed_literals.size());
  const auto anonymous = violations.count(kAnonymousPreference) ? violations.at(kAnonymousPreference) : 0.0;
  const auto& metric = world_.problem().metric;
  if (!metric) {
    verdict_.value = steps + anonymous;
    return true;
  }
  bool durative = false;
  for (const pddl::Requirement& r : world_.domain().requirements) {
    durative = durative || r.name == ":durative-actions" || r.name == ":time";
  }
  const State& measured = frozen ? *frozen : final_state;
  Binding none;
  Scope scope(world_, measured, none, conditions_);
  scope.total_time = durative ? (frozen ? frozen_time : end_time) : steps;
  scope.violations = &violations;
  verdict_.value = value(metric->expression, scope);
  // VAL's adjustment for unnamed preferences (its sign as VAL has it), which
  // it skips when timed literals follow the plan.
  if (!frozen) verdict_.value += metric->minimize ? -anonymous : anonymous;
  return true;
}

Judge::Judge(std::shared_ptr<const pddl::Domain> domain, std::shared_ptr<const pddl::Problem> problem,
             JudgeOptions options)
    : world_(std::move(domain), std::move(problem)), options_(options) {}

Judge::~Judge() = default;

const ActionParts& Judge::parts(const std::string& action) {
  auto it = parts_.find(action);
  if (it != parts_.end()) return it->second;
  ActionParts p = world_.action(action) ? parts_of(*world_.action(action)) : parts_of(*world_.durative_action(action));
  return parts_.emplace(action, std::move(p)).first->second;
}

Verdict Judge::judge(const TimedPlan& plan) {
  Run run(*this, plan);
  return run.run();
}

}  // namespace alplan::oracle
