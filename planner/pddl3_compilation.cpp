#include "planner/pddl3_compilation.h"

#include <algorithm>
#include <functional>

#include "pddl_parser/writer.h"
#include "planner/instantiate.h"
#include "planner/pddl3_order_constraints.h"
#include "planner/trajectory_monitor.h"

namespace alplan {
namespace {

void sort_unique(std::vector<FactId>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

void merge(ConditionSet& into, const ConditionSet& from) {
  into.positive.insert(into.positive.end(), from.positive.begin(), from.positive.end());
  into.negative.insert(into.negative.end(), from.negative.begin(), from.negative.end());
  into.numeric.insert(into.numeric.end(), from.numeric.begin(), from.numeric.end());
  into.complex.insert(into.complex.end(), from.complex.begin(), from.complex.end());
  into.mentioned.insert(into.mentioned.end(), from.mentioned.begin(), from.mentioned.end());
  into.mentioned_values.insert(into.mentioned_values.end(), from.mentioned_values.begin(), from.mentioned_values.end());
  into.ghost_mentioned.insert(into.ghost_mentioned.end(), from.ghost_mentioned.begin(), from.ghost_mentioned.end());
  if (from.never && !into.never) into.never = from.never;
  sort_unique(into.positive);
  sort_unique(into.negative);
  sort_unique(into.mentioned);
  sort_unique(into.mentioned_values);
  sort_unique(into.ghost_mentioned);
}

// What a condition reads, named in `into` without deciding anything there:
// a preference a round does not enforce still counts in VAL's mutex rule.
void mention(ConditionSet& into, const ConditionSet& from) {
  append_reads(from, into.mentioned, into.mentioned_values);
  into.ghost_mentioned.insert(into.ghost_mentioned.end(), from.ghost_mentioned.begin(), from.ghost_mentioned.end());
  sort_unique(into.mentioned);
  sort_unique(into.mentioned_values);
  sort_unique(into.ghost_mentioned);
}

// A condition as the disjunction of conditions a witness each can read: a
// single top-level disjunction splits into its disjuncts, each beside the
// rest of the condition.
std::vector<ConditionSet> disjuncts(const ConditionSet& c) {
  if (c.complex.size() != 1 || c.complex.front().kind != GroundFormula::Kind::Or) return {c};
  ConditionSet base = c;
  base.complex.clear();
  std::vector<ConditionSet> out;
  for (const GroundFormula& child : c.complex.front().children) {
    ConditionSet d = base;
    merge(d, flatten(child));
    if (!d.never) out.push_back(std::move(d));
  }
  if (out.empty()) {
    base.never = "no disjunct can hold";
    out.push_back(std::move(base));
  }
  return out;
}

// The operators pddl3_order_constraints.h compiles, each with its monitor facts.
bool order_operator(ModalOperator op) {
  return op == ModalOperator::AtMostOnce || op == ModalOperator::SometimeBefore ||
         op == ModalOperator::SometimeAfter || op == ModalOperator::HoldDuring || op == ModalOperator::HoldAfter;
}

bool compilable(ModalOperator op) {
  return op == ModalOperator::AtEnd || op == ModalOperator::Always || op == ModalOperator::Sometime ||
         op == ModalOperator::Within || op == ModalOperator::AlwaysWithin || order_operator(op);
}

bool holds_in(const std::vector<FactId>& facts, const ConditionSet& c) {
  auto in = [&](FactId f) { return std::find(facts.begin(), facts.end(), f) != facts.end(); };
  return std::all_of(c.positive.begin(), c.positive.end(), in) && std::none_of(c.negative.begin(), c.negative.end(), in);
}

// (is-violated p) of the compiled task: every enforced preference holds and
// the others are not the search's concern, so the metric reads 0 for each.
void drop_violation_terms(GroundExpression& e) {
  if (e.kind == GroundExpression::Kind::IsViolated) {
    e = GroundExpression{};
    return;
  }
  for (GroundExpression& operand : e.operands) drop_violation_terms(operand);
}

class Compiler {
 public:
  Compiler(const GroundTask& task, const PreferenceSelection& selection, const TrajectorySoFar& so_far, double epsilon)
      : source_(task), selection_(selection), so_far_(so_far), epsilon_(epsilon),
        start_facts_(so_far.facts ? *so_far.facts : task.initial_facts), lifted_(std::make_shared<NormalizedTask>(*task.lifted)),
        out_(std::make_shared<GroundTask>(task)) {
    out_->lifted = lifted_;
    out_->pddl3 = GroundTrajectory{};
    lifted_->pddl3 = TrajectoryConstraints{};
    lifted_->pddl3.preferences = task.lifted->pddl3.preferences;
    if (out_->metric) drop_violation_terms(out_->metric->expression);
  }

  CompiledTrajectory run() {
    CompiledTrajectory result;
    for (std::size_t k = 0; k < source_.pddl3.constraints.size(); ++k) {
      const GroundConstraint& g = source_.pddl3.constraints[k];
      if (g.preference && !selection_.contains(*g.preference)) continue;
      if (so_far_.seen) {
        const std::optional<std::string> settled = settled_before(k, g);
        if (settled && !g.preference && !settled->empty()) {
          result.broken = g.text + ": " + *settled;
          return result;
        }
        if (settled) continue;
        if (g.op == ModalOperator::AlwaysWithin && !g.preference && so_far_.seen->deadline_open(k)) {
          result.refused = g.text + ": the planner cannot plan on with a hard `always-within` deadline opened "
                           "before the observed state";
          return result;
        }
      }
      if (order_operator(g.op)) {
        if (std::optional<std::string> why = order_constraint(k, g)) {
          if (g.preference) continue;  // not enforced: its violations count
          result.refused = g.text + ": the planner cannot plan with this hard `" + to_string(g.op) +
                           "` constraint: " + *why;
          return result;
        }
        continue;
      }
      if (g.op == ModalOperator::AlwaysWithin) {
        // A preference a round enforces takes the hard form's watches where
        // it can; otherwise (or from an observed state, where a deadline may
        // be open) its violations count.
        if (g.preference && so_far_.seen) continue;
        if (std::optional<std::string> why = watch(k, g)) {
          if (g.preference) continue;
          result.refused = g.text + ": the planner cannot plan with this hard `always-within` constraint: " + *why;
          return result;
        }
        continue;
      }
      if (!compilable(g.op)) {
        if (!g.preference) {
          result.refused = g.text + ": the planner cannot plan with a hard `" + to_string(g.op) + "` constraint";
          return result;
        }
        continue;  // never enforced (enforceable() says no)
      }
      constraint(k, g);
    }
    for (const GroundPreference& p : source_.pddl3.goal_preferences) {
      if (selection_.contains(p.preference)) merge(out_->goal, p.condition);
    }
    action_preferences();
    goal_axioms();
    sort_unique(out_->goal.positive);
    result.task = out_;
    return result;
  }

 private:
  // What the states seen before the start settle about constraint k: empty
  // when it is met already, why it is violated when it is; none when the
  // plan still decides.
  std::optional<std::string> settled_before(std::size_t k, const GroundConstraint& g) const {
    const TrajectoryMonitor& seen = *so_far_.seen;
    if (seen.broken(k)) return std::string("violated before the observed state");
    const bool eventually = g.op == ModalOperator::Sometime || g.op == ModalOperator::Within;
    if (eventually && seen.met(k)) return std::string();
    if (g.op == ModalOperator::Within && g.deadline < so_far_.now) {
      return "not reached by " + pddl::format_number(g.deadline) + ", before the observed state";
    }
    return std::nullopt;
  }

  void constraint(std::size_t k, const GroundConstraint& g) {
    switch (g.op) {
      case ModalOperator::AtEnd: merge(out_->goal, g.requirement); return;
      case ModalOperator::Always: {
        GroundConstraint hard = g;
        hard.preference.reset();
        hard.monitor = out_->pddl3.monitors++;
        out_->pddl3.constraints.push_back(std::move(hard));
        return;
      }
      case ModalOperator::Sometime: witness(k, g.requirement, std::nullopt); return;
      case ModalOperator::Within: witness(k, g.requirement, witness_deadline(g.deadline)); return;
      default: return;
    }
  }

  // A hard (always-within t φ ψ) with φ one fact f, in the form the
  // header names: a durative watch of at most t that adds `pddl3-watching-K` at its
  // start and needs ψ at its end; each snap that adds f needs a watch
  // running, and each snap that breaks ψ needs a watch running or f false
  // (pddl3_compilation.h says why that is enough). The reason it cannot,
  // otherwise.
  std::optional<std::string> watch(std::size_t k, const GroundConstraint& g) {
    const ConditionSet& trigger = g.trigger;
    if (trigger.positive.size() != 1 || !trigger.negative.empty() || !trigger.numeric.empty() ||
        !trigger.complex.empty()) {
      return std::string("its trigger is not a single fact");
    }
    const ConditionSet& requirement = g.requirement;
    if (!requirement.numeric.empty() || !requirement.complex.empty()) {
      return std::string("its requirement is not a conjunction of literals");
    }
    const FactId f = trigger.positive.front();
    if (holds_in(start_facts_, trigger)) return std::string("its trigger holds in the initial state");
    // What ψ's literals lose by: their facts deleted where positive, added where negative.
    auto breaks_requirement = [&](FactId fact, bool added) {
      const std::vector<FactId>& lost = added ? requirement.negative : requirement.positive;
      return std::find(lost.begin(), lost.end(), fact) != lost.end();
    };
    for (const GroundTimedLiteral& til : source_.timed_literals) {
      if (til.fact == f && til.positive) return std::string("a timed literal adds its trigger");
      // A timed literal takes no condition, so it cannot be made to wait for a watch.
      if (breaks_requirement(til.fact, til.positive)) return std::string("a timed literal breaks its requirement");
    }
    const std::string id = std::to_string(k);
    const FactId watching = new_fact("pddl3-watching-" + id);
    GroundAction w;
    w.schema = new_schema("pddl3-watch-" + id);
    w.durative = true;
    w.at_end = requirement;
    w.start.add.push_back(watching);
    w.end.del.push_back(watching);
    GroundDurationConstraint at_most;
    at_most.comparison = pddl::Comparison::LessEqual;
    at_most.value.kind = GroundExpression::Kind::Constant;
    at_most.value.value = g.deadline;
    w.duration.push_back(std::move(at_most));
    // Needs a watch, or the trigger false: breaking ψ where f holds opens a deadline.
    GroundFormula watched_or_quiet;
    watched_or_quiet.kind = GroundFormula::Kind::Or;
    for (const auto& [fact, positive] : {std::pair{watching, true}, std::pair{f, false}}) {
      GroundFormula literal;
      literal.kind = GroundFormula::Kind::Literal;
      literal.fact = fact;
      literal.positive = positive;
      watched_or_quiet.children.push_back(literal);
    }
    // Conditional effects count as if their condition held: a watch more
    // than needed costs plans, one fewer would cost validity.
    auto any_write = [](const HappeningEffects& e, const std::function<bool(FactId, bool)>& test) {
      auto in = [&](const std::vector<FactId>& add, const std::vector<FactId>& del) {
        return std::any_of(add.begin(), add.end(), [&](FactId x) { return test(x, true); }) ||
               std::any_of(del.begin(), del.end(), [&](FactId x) { return test(x, false); });
      };
      return in(e.add, e.del) ||
             std::any_of(e.conditional.begin(), e.conditional.end(),
                         [&](const ConditionalEffect& c) { return in(c.add, c.del); });
    };
    auto breaks = [&](const HappeningEffects& e) { return any_write(e, breaks_requirement); };
    auto adds_trigger = [&](const HappeningEffects& e) {
      return any_write(e, [&](FactId x, bool added) { return added && x == f; });
    };
    std::vector<GroundAction>& actions = out_->actions.mutate();
    for (std::size_t a = 0; a < source_.actions.size(); ++a) {
      GroundAction& action = actions[a];
      for (auto [effects, condition] : {std::pair{&action.start, &action.at_start}, std::pair{&action.end, &action.at_end}}) {
        if (adds_trigger(*effects)) {
          condition->positive.push_back(watching);
          sort_unique(condition->positive);
        } else if (breaks(*effects)) {
          condition->complex.push_back(watched_or_quiet);
        }
      }
    }
    out_->actions.push_back(std::move(w));
    out_->pddl3.approximations.push_back("the hard constraint " + g.text +
                                         " was planned with watches of at most its span, which may miss plans");
    return std::nullopt;
  }

  // An order constraint compiled (pddl3_order_constraints.h), or why not.
  // From an observed state its monitor would need what the states before
  // it did, which the compiled task cannot start from.
  std::optional<std::string> order_constraint(std::size_t k, const GroundConstraint& g) {
    if (so_far_.seen) return std::string("not from an observed state (its history is not compiled)");
    OrderCompilation c{*out_, source_.actions.size(), start_facts_,
                       [this](const std::string& name) { return new_fact(name); },
                       [this](std::size_t key, const ConditionSet& condition, FactId fact, bool deletes) {
                         add_witnesses(key, condition, fact, deletes, std::nullopt);
                       }};
    switch (g.op) {
      case ModalOperator::AtMostOnce: return compile_at_most_once(c, k, g);
      case ModalOperator::SometimeBefore: return compile_sometime_before(c, k, g);
      case ModalOperator::SometimeAfter: return compile_sometime_after(c, k, g);
      default: return compile_hold(c, k, g);
    }
  }

  // Each disjunction left in the goal (an `at end` of an `exists`, as
  // storage's crates in some depot) becomes a derived fact, one axiom per
  // disjunct, and the goal asks the fact: the same states meet it, and the
  // temporal relaxed planning graph, which reads the goal's facts and the
  // axioms' bodies, sees what the goal needs (it reads no formula: without
  // this, a goal made only of disjunctions left the heuristic no goal).
  void goal_axioms() {
    if (out_->goal.complex.empty()) return;
    std::vector<GroundFormula> kept;
    const std::uint32_t stratum = out_->strata;
    for (std::size_t k = 0; k < out_->goal.complex.size(); ++k) {
      const GroundFormula& f = out_->goal.complex[k];
      if (f.kind != GroundFormula::Kind::Or) {
        kept.push_back(f);
        continue;
      }
      const auto predicate = static_cast<PredicateId>(lifted_->predicates.size());
      std::string name = "pddl3-goal-" + std::to_string(k);
      while (std::any_of(lifted_->predicates.begin(), lifted_->predicates.end(),
                         [&](const PredicateInfo& p) { return p.name == name; })) {
        name += "'";
      }
      lifted_->predicates.push_back(PredicateInfo{name, {}, true, false});
      const FactId head = out_->facts.intern(GroundKey{predicate, {}});
      for (const GroundFormula& disjunct : f.children) {
        ConditionSet body = flatten(disjunct);
        if (body.never) continue;
        out_->axioms.push_back(GroundAxiom{head, std::move(body), stratum});
      }
      out_->goal.positive.push_back(head);
    }
    out_->goal.complex = std::move(kept);
    out_->strata = stratum + 1;
  }

  std::uint32_t new_schema(const std::string& name) {
    ActionSchema named;
    named.name = name;
    while (lifted_->find_action(named.name)) named.name += "'";
    lifted_->actions.push_back(std::move(named));
    return static_cast<std::uint32_t>(lifted_->actions.size() - 1);
  }

  FactId new_fact(const std::string& name) {
    const auto predicate = static_cast<PredicateId>(lifted_->predicates.size());
    lifted_->predicates.push_back(PredicateInfo{name, {}, false, true});
    return out_->facts.intern(GroundKey{predicate, {}});
  }

  // When a `within t` witness may read: VAL asks for a state at or before
  // t, and the state a snap reads is the one after the last write of what
  // it reads, epsilon or more before it. A witness reading up to epsilon
  // after t (`pddl3-open-K` closed at t + 2 epsilon, which the witness reads
  // epsilon before) therefore sees what the happenings up to t made, and
  // nothing later: φ made true at t itself counts, as in VAL. With
  // continuous change a value read epsilon after t is not the value at t:
  // there the literal closes at t, so φ must be made by t - 2 epsilon, and a
  // plan meeting it later is lost (an exhausted search there is no proof
  // anyway).
  double witness_deadline(double deadline) const { return continuous_ ? deadline : deadline + 2 * epsilon_; }

  void witness(std::size_t k, const ConditionSet& requirement, std::optional<double> deadline) {
    const std::string id = std::to_string(k);
    const FactId done = new_fact("pddl3-done-" + id);
    out_->goal.positive.push_back(done);
    std::optional<FactId> open;
    if (deadline) {
      open = new_fact("pddl3-open-" + id);
      out_->initial_facts.push_back(*open);
      sort_unique(out_->initial_facts);
      insert_timed_literal(*out_, {*deadline, *open, false});
    }
    add_witnesses(k, requirement, done, false, open);
  }

  // Instantaneous actions, one per disjunct of `requirement` (and `open`
  // where set), that add `fact` (delete it, where `deletes`).
  void add_witnesses(std::size_t k, const ConditionSet& requirement, FactId fact, bool deletes,
                     std::optional<FactId> open) {
    const std::uint32_t schema = new_schema("pddl3-witness-" + std::to_string(k));
    for (ConditionSet condition : disjuncts(requirement)) {
      GroundAction w;
      w.schema = schema;
      if (open) condition.positive.push_back(*open);
      sort_unique(condition.positive);
      w.at_start = std::move(condition);
      (deletes ? w.start.del : w.start.add).push_back(fact);
      out_->actions.push_back(std::move(w));
    }
  }

  // Enforced precondition preferences join the action's conditions; the
  // others leave the action (the validator counts them on the plan), what
  // they read still named for VAL's mutex rule.
  void action_preferences() {
    const bool any = std::any_of(source_.actions.begin(), source_.actions.end(),
                                 [](const GroundAction& a) { return !a.preferences.empty(); });
    if (!any) return;
    for (GroundAction& a : out_->actions.mutate()) {
      for (const GroundPreference& p : a.preferences) {
        if (!selection_.contains(p.preference)) {
          if (!a.durative || p.time == pddl::TimeSpecifier::AtStart) mention(a.at_start, p.condition);
          if (a.durative && p.time == pddl::TimeSpecifier::AtEnd) mention(a.at_end, p.condition);
          continue;
        }
        if (!a.durative || p.time == pddl::TimeSpecifier::AtStart) {
          merge(a.at_start, p.condition);
        } else if (p.time == pddl::TimeSpecifier::AtEnd) {
          merge(a.at_end, p.condition);
        } else {
          merge(a.over_all, p.condition);
        }
      }
      a.preferences.clear();
    }
    for (ActionSchema& schema : lifted_->actions) schema.preferences.clear();
  }

  const GroundTask& source_;
  const PreferenceSelection& selection_;
  const TrajectorySoFar& so_far_;
  double epsilon_;
  bool continuous_ = std::any_of(source_.actions.begin(), source_.actions.end(),
                                 [](const GroundAction& a) { return !a.continuous.empty(); });
  const std::vector<FactId>& start_facts_;
  std::shared_ptr<NormalizedTask> lifted_;
  std::shared_ptr<GroundTask> out_;
};

}  // namespace

bool needs_compilation(const GroundTask& task) {
  if (!task.pddl3.goal_preferences.empty()) return true;
  for (const GroundConstraint& g : task.pddl3.constraints) {
    if (g.preference || g.op != ModalOperator::Always) return true;
  }
  return std::any_of(task.actions.begin(), task.actions.end(),
                     [](const GroundAction& a) { return !a.preferences.empty(); });
}

bool enforceable(const GroundTask& task, std::uint32_t preference) {
  return std::all_of(task.pddl3.constraints.begin(), task.pddl3.constraints.end(), [&](const GroundConstraint& g) {
    return g.preference != preference || compilable(g.op);
  });
}

CompiledTrajectory compile_trajectory(const GroundTask& task, const PreferenceSelection& selection,
                                      const TrajectorySoFar& so_far, double epsilon) {
  return Compiler(task, selection, so_far, epsilon).run();
}

}  // namespace alplan
