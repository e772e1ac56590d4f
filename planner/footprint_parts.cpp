#include "planner/footprint_parts.h"

namespace alplan::footprint_parts {

namespace {

bool mentions_duration(const GroundExpression& e) {
  if (e.kind == GroundExpression::Kind::Duration) return true;
  return std::any_of(e.operands.begin(), e.operands.end(), mentions_duration);
}

bool additive(pddl::AssignOperator op) {
  return op == pddl::AssignOperator::Increase || op == pddl::AssignOperator::Decrease;
}

}  // namespace

void condition_reads(const ConditionSet& c, Footprint& fp) { append_reads(c, fp.reads, fp.reads_values); }

void condition_holds(const ConditionSet& c, Footprint& fp) { append_reads(c, fp.holds, fp.holds_values); }

void effect_footprint(const HappeningEffects& e, Footprint& fp, const std::vector<std::uint32_t>& skipped) {
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

}  // namespace alplan::footprint_parts
