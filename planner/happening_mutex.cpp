// The mutex rule of a happening (VAL's Ownership): what each member reads
// and writes, and the clashes between members. Part of HappeningExecutor,
// apart from its execution of the happening, so each file holds one idea.
#include <algorithm>

#include "planner/formula_evaluation.h"
#include "planner/happening_executor.h"

namespace alplan {
namespace {

void collect_facts(const GroundFormula& f, std::set<FactId>& out) {
  if (f.kind == GroundFormula::Kind::Literal) out.insert(f.fact);
  for (const GroundFormula& child : f.children) collect_facts(child, out);
}

void collect_variables(const GroundExpression& e, std::set<NumericVarId>& out) {
  if (e.kind == GroundExpression::Kind::Variable) out.insert(e.variable);
  for (const GroundExpression& operand : e.operands) collect_variables(operand, out);
}

void collect_variables(const GroundFormula& f, std::set<NumericVarId>& out) {
  if (f.kind == GroundFormula::Kind::Comparison) {
    collect_variables(f.comparison.left, out);
    collect_variables(f.comparison.right, out);
  }
  for (const GroundFormula& child : f.children) collect_variables(child, out);
}

// Atoms and values named where they decide nothing (ConditionSet::mentioned:
// simplified away, or a precondition preference a round of the preference
// search leaves out) count too: VAL reads every proposition a precondition
// names (the differential tester's task 8589948526, a dropped preference's
// read with a fact added twice).
void collect_reads(const ConditionSet& c, std::set<FactId>& facts, std::set<NumericVarId>& values) {
  facts.insert(c.positive.begin(), c.positive.end());
  facts.insert(c.negative.begin(), c.negative.end());
  facts.insert(c.mentioned.begin(), c.mentioned.end());
  values.insert(c.mentioned_values.begin(), c.mentioned_values.end());
  for (const GroundComparison& cmp : c.numeric) {
    collect_variables(cmp.left, values);
    collect_variables(cmp.right, values);
  }
  for (const GroundFormula& f : c.complex) {
    collect_facts(f, facts);
    collect_variables(f, values);
  }
}

bool additive(pddl::AssignOperator op) {
  return op == pddl::AssignOperator::Increase || op == pddl::AssignOperator::Decrease;
}

}  // namespace

HappeningExecutor::Footprint HappeningExecutor::footprint(const Event& e) const {
  Footprint f;
  if (e.point == Point::Til) {
    const GroundTimedLiteral& til = task_.timed_literals[e.scheduled];
    (til.positive ? f.adds : f.dels).insert(til.fact);
    return f;
  }
  const GroundAction& action = *action_of(e);
  collect_reads(e.point == Point::End ? action.at_end : action.at_start, f.reads, f.reads_values);
  // VAL's mutex rule reads the propositions of preferences too.
  const pddl::TimeSpecifier at = e.point == Point::End ? pddl::TimeSpecifier::AtEnd : pddl::TimeSpecifier::AtStart;
  for (const GroundPreference& p : action.preferences) {
    if (p.time == at) collect_reads(p.condition, f.reads, f.reads_values);
  }
  // A condition on a derived fact reads what it is derived from (VAL).
  auto expand_derived = [&](std::set<FactId>& reads, std::set<NumericVarId>& values) {
    if (task_.axioms.empty()) return;
    if (!derived_) derived_ = std::make_unique<DerivedSupport>(task_);
    const std::vector<FactId> read(reads.begin(), reads.end());
    for (FactId p : read) {
      if (!task_.is_derived(p)) continue;
      const DerivedSupport::Support& s = derived_->of(p);
      reads.insert(s.facts.begin(), s.facts.end());
      values.insert(s.variables.begin(), s.variables.end());
    }
  };
  expand_derived(f.reads, f.reads_values);
  for (const GroundDurationConstraint& d : action.duration) collect_variables(d.value, f.reads_values);
  const HappeningEffects& effects = e.point == Point::End ? action.end : action.start;
  const EvaluationContext context = context_of(e);
  std::set<FactId> changed;  // by this event so far, in VAL's order
  f.claimed_reads = f.reads;
  f.added_again.insert(effects.added_twice.begin(), effects.added_twice.end());
  auto add_effects = [&](const std::vector<FactId>& adds, const std::vector<FactId>& dels,
                         const std::vector<NumericAssignment>& numeric) {
    for (FactId p : adds) {
      if (!changed.insert(p).second) f.added_again.insert(p);
    }
    changed.insert(dels.begin(), dels.end());
    f.adds.insert(adds.begin(), adds.end());
    f.dels.insert(dels.begin(), dels.end());
    for (const NumericAssignment& a : numeric) {
      collect_variables(a.value, f.reads_values);
      f.writes.emplace_back(a.variable, a.assign);
    }
  };
  add_effects(effects.add, effects.del, effects.numeric);
  for (const ConditionalEffect& c : effects.conditional) {
    if (!holds(c.condition, state_, context, numeric_slack_)) continue;
    // VAL claims a firing condition's reads when it constructs that effect
    // (Action::handleEffects): a fact this event has not yet changed is
    // claimed as read, and adding it twice afterwards is the added-and-read
    // mutex. One it has changed stays owned as written, so whether another
    // member's write of it is a mutex depends on which of the two the plan
    // lists first (VAL 3c7a1f3 refuses `0: (n)`, `0: (m)` and accepts
    // `0: (m)`, `0: (n)` where m deletes p and reads it in a conditional
    // effect and n deletes it). A plan's listing order is no part of its
    // meaning: every fact a firing condition reads counts as a read against
    // the other members, so what passes here passes VAL in any order.
    std::set<FactId> condition_reads;
    collect_reads(c.condition, condition_reads, f.reads_values);
    expand_derived(condition_reads, f.reads_values);
    for (FactId p : condition_reads) {
      f.reads.insert(p);
      if (!changed.count(p)) f.claimed_reads.insert(p);
    }
    add_effects(c.add, c.del, c.numeric);
  }
  return f;
}

std::optional<Violation> HappeningExecutor::check_mutex(const std::vector<Event>& events) {
  std::vector<Footprint> prints;
  for (const Event& e : events) prints.push_back(footprint(e));
  auto clash = [&](std::size_t a, std::size_t b, std::string what) {
    Violation v = violation(Violation::Kind::MutexViolation, events[a]);
    v.condition = std::move(what);
    v.other_action = event_name(events[b]);
    return v;
  };
  for (std::size_t a = 0; a < events.size(); ++a) {
    const Footprint& fa = prints[a];
    // VAL marks what an action reads only when its happening has other
    // members; a second add of such a fact by the same action then finds
    // it owned as added-and-read and is a mutex (Ownership::ownsForAdd).
    for (FactId p : fa.added_again) {
      if (events.size() > 1 && fa.claimed_reads.count(p)) {
        return clash(a, a, "adds " + task_.fact_name(p) + " twice while it reads it, with other members in its happening");
      }
    }
    for (std::size_t i = 0; i < fa.writes.size(); ++i) {
      for (std::size_t j = i + 1; j < fa.writes.size(); ++j) {
        if (fa.writes[i].first == fa.writes[j].first && !(additive(fa.writes[i].second) && additive(fa.writes[j].second))) {
          return clash(a, a, "assigns to " + task_.variable_name(fa.writes[i].first) + " twice");
        }
      }
    }
    for (std::size_t b = 0; b < events.size(); ++b) {
      if (a == b) continue;
      const Footprint& fb = prints[b];
      for (FactId p : fa.reads) {
        if (fb.adds.count(p)) return clash(b, a, "adds " + task_.fact_name(p) + ", which the other requires");
        if (fb.dels.count(p)) return clash(b, a, "deletes " + task_.fact_name(p) + ", which the other requires");
      }
      for (FactId p : fa.adds) {
        if (fb.dels.count(p)) return clash(a, b, "adds " + task_.fact_name(p) + ", which the other deletes");
      }
      for (const auto& [variable, op] : fb.writes) {
        if (fa.reads_values.count(variable)) {
          return clash(b, a, "changes " + task_.variable_name(variable) + ", which the other reads");
        }
        for (const auto& [other, other_op] : fa.writes) {
          if (other == variable && !(additive(op) && additive(other_op))) {
            return clash(b, a, "changes " + task_.variable_name(variable) + ", which the other also changes");
          }
        }
      }
    }
  }
  return std::nullopt;
}

}  // namespace alplan
