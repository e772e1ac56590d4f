#include "planner/pddl3_order_constraints.h"

#include <algorithm>

#include "pddl_parser/writer.h"

namespace alplan {
namespace {

void sort_unique(std::vector<FactId>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

bool contains(const std::vector<FactId>& v, FactId f) { return std::find(v.begin(), v.end(), f) != v.end(); }

bool any_of_facts(const std::vector<FactId>& written, const std::vector<FactId>& facts) {
  return std::any_of(written.begin(), written.end(), [&](FactId f) { return contains(facts, f); });
}

// Facts of an Or of positive literals (nested Ors flattened); false for any
// other formula.
bool collect_disjunction(const GroundFormula& f, std::vector<FactId>& out) {
  switch (f.kind) {
    case GroundFormula::Kind::Literal:
      if (!f.positive) return false;
      out.push_back(f.fact);
      return true;
    case GroundFormula::Kind::False: return true;
    case GroundFormula::Kind::Or:
      return std::all_of(f.children.begin(), f.children.end(),
                         [&](const GroundFormula& child) { return collect_disjunction(child, out); });
    default: return false;
  }
}

// One snap of an original action: its effects and the condition read
// before them.
struct Snap {
  HappeningEffects* effects;
  ConditionSet* condition;
  Moment moment;
};

std::vector<Snap> snaps_of(GroundTask& task, std::size_t count) {
  std::vector<Snap> out;
  std::vector<GroundAction>& actions = task.actions.mutate();
  for (std::size_t a = 0; a < count && a < actions.size(); ++a) {
    GroundAction& action = actions[a];
    out.push_back({&action.start, &action.at_start, Moment::Start});
    if (action.durative) out.push_back({&action.end, &action.at_end, Moment::End});
  }
  return out;
}

bool adds_unconditionally(const Snap& s, const std::vector<FactId>& facts) { return any_of_facts(s.effects->add, facts); }

bool adds_conditionally(const Snap& s, const std::vector<FactId>& facts) {
  return std::any_of(s.effects->conditional.begin(), s.effects->conditional.end(),
                     [&](const ConditionalEffect& c) { return any_of_facts(c.add, facts); });
}

// Why a timed literal defeats the compilation (it takes no condition and
// no conditional effect), or nullopt.
std::optional<std::string> timed_literal_writes(const GroundTask& task, const std::vector<FactId>& facts, bool adds_only) {
  for (const GroundTimedLiteral& til : task.timed_literals) {
    if (contains(facts, til.fact) && (til.positive || !adds_only)) {
      return std::string("a timed literal at ") + pddl::format_number(til.time) + " writes a fact of its condition";
    }
  }
  return std::nullopt;
}

// φ's facts (fact_disjunction), or why the compilation cannot take φ: its
// form, or a timed literal that adds one of its facts (or, where
// `timed_deletes_too`, deletes one). No fact: φ never holds.
std::optional<std::string> phi_facts(const GroundTask& task, const ConditionSet& phi, bool timed_deletes_too,
                                     std::vector<FactId>& facts) {
  std::optional<std::vector<FactId>> d = fact_disjunction(phi);
  if (!d) return std::string("its condition is not a fact or a disjunction of facts");
  facts = std::move(*d);
  return timed_literal_writes(task, facts, !timed_deletes_too);
}

void approximate(OrderCompilation& c, const GroundConstraint& g) {
  c.task.pddl3.approximations.push_back("the constraint " + g.text +
                                        " was planned with its facts' changes seen snap by snap, stricter than VAL's "
                                        "happenings, which may miss plans");
}

// φ as a formula: the conjunction of everything the set holds.
GroundFormula as_formula(const ConditionSet& c) {
  GroundFormula all;
  all.kind = GroundFormula::Kind::And;
  if (c.never) {
    all.kind = GroundFormula::Kind::False;
    all.reason = *c.never;
    return all;
  }
  for (const auto* list : {&c.positive, &c.negative}) {
    for (FactId f : *list) {
      GroundFormula literal;
      literal.kind = GroundFormula::Kind::Literal;
      literal.fact = f;
      literal.positive = list == &c.positive;
      all.children.push_back(literal);
    }
  }
  for (const GroundComparison& n : c.numeric) {
    GroundFormula comparison;
    comparison.kind = GroundFormula::Kind::Comparison;
    comparison.comparison = n;
    all.children.push_back(comparison);
  }
  all.children.insert(all.children.end(), c.complex.begin(), c.complex.end());
  return all;
}

}  // namespace

void insert_timed_literal(GroundTask& task, GroundTimedLiteral literal) {
  auto& tils = task.timed_literals;
  tils.insert(std::upper_bound(tils.begin(), tils.end(), literal,
                               [](const GroundTimedLiteral& a, const GroundTimedLiteral& b) { return a.time < b.time; }),
              literal);
}

std::optional<std::vector<FactId>> fact_disjunction(const ConditionSet& phi) {
  if (phi.never) return std::vector<FactId>{};
  if (!phi.numeric.empty() || !phi.negative.empty()) return std::nullopt;
  if (phi.complex.empty()) {
    if (phi.positive.size() != 1) return std::nullopt;
    return phi.positive;
  }
  if (!phi.positive.empty() || phi.complex.size() != 1) return std::nullopt;
  std::vector<FactId> facts;
  if (!collect_disjunction(phi.complex.front(), facts)) return std::nullopt;
  sort_unique(facts);
  return facts;
}

std::optional<std::string> compile_at_most_once(OrderCompilation& c, std::size_t k, const GroundConstraint& g) {
  std::vector<FactId> phi;
  if (std::optional<std::string> why = phi_facts(c.task, g.requirement, true, phi)) return why;
  if (phi.empty()) return std::nullopt;  // φ never holds: met
  const FactId closed = c.new_fact("pddl3-closed-" + std::to_string(k));
  for (const Snap& s : snaps_of(c.task, c.source_actions)) {
    const bool adds = adds_unconditionally(s, phi);
    if (adds || adds_conditionally(s, phi)) {
      s.condition->negative.push_back(closed);
      sort_unique(s.condition->negative);
    }
    if (adds) continue;  // φ holds after it
    // φ stops where a deleted fact held and no other fact of φ does.
    std::vector<FactId> deleted;
    for (FactId f : s.effects->del) {
      if (contains(phi, f)) deleted.push_back(f);
    }
    std::vector<FactId> others;
    for (FactId f : phi) {
      if (!contains(deleted, f)) others.push_back(f);
    }
    const std::size_t count = s.effects->conditional.size();
    for (FactId f : deleted) {
      ConditionalEffect close;
      close.condition.positive = {f};
      close.condition.negative = others;
      close.condition_moment = s.moment;
      close.add = {closed};
      s.effects->conditional.push_back(std::move(close));
    }
    // A conditional delete closes φ under its own condition; a conditional
    // add beside it that fires too is read as not firing (stricter).
    for (std::size_t e = 0; e < count; ++e) {
      const ConditionalEffect effect = s.effects->conditional[e];
      for (FactId f : effect.del) {
        if (!contains(phi, f)) continue;
        ConditionalEffect close;
        close.condition = effect.condition;
        close.condition_moment = effect.condition_moment;
        close.condition.positive.push_back(f);
        for (FactId o : phi) {
          if (o != f && !contains(deleted, o) && !contains(effect.del, o)) close.condition.negative.push_back(o);
        }
        sort_unique(close.condition.positive);
        sort_unique(close.condition.negative);
        close.add = {closed};
        s.effects->conditional.push_back(std::move(close));
      }
    }
  }
  approximate(c, g);
  return std::nullopt;
}

std::optional<std::string> compile_sometime_before(OrderCompilation& c, std::size_t k, const GroundConstraint& g) {
  std::vector<FactId> phi;
  if (std::optional<std::string> why = phi_facts(c.task, g.trigger, false, phi)) return why;
  if (phi.empty()) return std::nullopt;  // φ never holds: met
  if (any_of_facts(c.start_facts, phi)) {
    return std::string("its first condition holds in the first state, with no state before it");
  }
  const FactId seen = c.new_fact("pddl3-seen-" + std::to_string(k));
  c.witness(k, g.requirement, seen, false);
  for (const Snap& s : snaps_of(c.task, c.source_actions)) {
    if (adds_unconditionally(s, phi) || adds_conditionally(s, phi)) {
      s.condition->positive.push_back(seen);
      sort_unique(s.condition->positive);
    }
  }
  approximate(c, g);
  return std::nullopt;
}

std::optional<std::string> compile_sometime_after(OrderCompilation& c, std::size_t k, const GroundConstraint& g) {
  std::vector<FactId> phi;
  if (std::optional<std::string> why = phi_facts(c.task, g.trigger, false, phi)) return why;
  if (phi.empty()) return std::nullopt;  // φ never holds: met
  const FactId pending = c.new_fact("pddl3-pending-" + std::to_string(k));
  for (const Snap& s : snaps_of(c.task, c.source_actions)) {
    if (adds_unconditionally(s, phi)) {
      s.effects->add.push_back(pending);
      sort_unique(s.effects->add);
    }
    const std::size_t count = s.effects->conditional.size();
    for (std::size_t e = 0; e < count; ++e) {
      if (any_of_facts(s.effects->conditional[e].add, phi)) s.effects->conditional[e].add.push_back(pending);
    }
    // The state before this snap, where φ holds, waits for ψ.
    for (FactId f : phi) {
      ConditionalEffect mark;
      mark.condition.positive = {f};
      mark.condition_moment = s.moment;
      mark.add = {pending};
      s.effects->conditional.push_back(std::move(mark));
    }
  }
  c.witness(k, g.requirement, pending, true);
  c.task.goal.negative.push_back(pending);
  sort_unique(c.task.goal.negative);
  if (any_of_facts(c.start_facts, phi)) {
    c.task.initial_facts.push_back(pending);
    sort_unique(c.task.initial_facts);
  }
  approximate(c, g);
  return std::nullopt;
}

std::optional<std::string> compile_hold(OrderCompilation& c, std::size_t k, const GroundConstraint& g) {
  const bool during = g.op == ModalOperator::HoldDuring;
  const double from = during ? g.from : g.deadline;
  if (during && !(g.from < g.deadline)) return std::nullopt;  // an empty interval: met
  const FactId open = c.new_fact("pddl3-holding-" + std::to_string(k));
  if (from > 0.0) {
    insert_timed_literal(c.task, {from, open, true});
  } else {
    c.task.initial_facts.push_back(open);
    sort_unique(c.task.initial_facts);
  }
  if (during) insert_timed_literal(c.task, {g.deadline, open, false});
  GroundFormula quiet;
  quiet.kind = GroundFormula::Kind::Literal;
  quiet.fact = open;
  quiet.positive = false;
  GroundFormula either;
  either.kind = GroundFormula::Kind::Or;
  either.children = {quiet, as_formula(g.requirement)};
  GroundConstraint hard;
  hard.op = ModalOperator::Always;
  hard.requirement.complex.push_back(std::move(either));
  hard.monitor = c.task.pddl3.monitors++;
  hard.text = g.text;
  c.task.pddl3.constraints.push_back(std::move(hard));
  approximate(c, g);
  return std::nullopt;
}

}  // namespace alplan
