#include "planner/derived_support.h"

#include <algorithm>
#include <set>

namespace alplan {
namespace {

void expression_functions(const LiftedExpression& e, std::set<FunctionId>& functions) {
  if (e.kind == LiftedExpression::Kind::Function) functions.insert(e.term.function);
  for (const LiftedExpression& o : e.operands) expression_functions(o, functions);
}

void condition_mentions(const LiftedCondition& c, std::set<PredicateId>& predicates, std::set<FunctionId>& functions) {
  if (c.kind == LiftedCondition::Kind::Atom) predicates.insert(c.atom.predicate);
  for (const LiftedExpression& e : c.sides) expression_functions(e, functions);
  for (const LiftedCondition& child : c.children) condition_mentions(child, predicates, functions);
}

}  // namespace

LiftedDerivedReads::LiftedDerivedReads(const NormalizedTask& lifted)
    : predicates_(lifted.predicates.size()), functions_(lifted.predicates.size()) {
  // What each derived predicate's own rules mention.
  std::vector<std::set<PredicateId>> direct(lifted.predicates.size());
  std::vector<std::set<FunctionId>> direct_functions(lifted.predicates.size());
  std::vector<bool> derived(lifted.predicates.size(), false);
  for (const DerivedRule& rule : lifted.derived_rules) {
    derived[rule.head] = true;
    condition_mentions(rule.body, direct[rule.head], direct_functions[rule.head]);
  }
  // The closure through derived predicates, by a search from each (the
  // rules may be recursive).
  for (PredicateId p = 0; p < lifted.predicates.size(); ++p) {
    if (!derived[p]) continue;
    std::set<PredicateId> basic, seen{p};
    std::set<FunctionId> functions;
    std::vector<PredicateId> open{p};
    while (!open.empty()) {
      const PredicateId d = open.back();
      open.pop_back();
      functions.insert(direct_functions[d].begin(), direct_functions[d].end());
      for (PredicateId q : direct[d]) {
        if (!derived[q]) {
          basic.insert(q);
        } else if (seen.insert(q).second) {
          open.push_back(q);
        }
      }
    }
    predicates_[p].assign(basic.begin(), basic.end());
    functions_[p].assign(functions.begin(), functions.end());
  }
}

DerivedSupport::DerivedSupport(const GroundTask& task) : task_(task) {
  for (std::uint32_t x = 0; x < task.axioms.size(); ++x) by_head_[task.axioms[x].head].push_back(x);
}

const DerivedSupport::Support& DerivedSupport::of(FactId derived) {
  if (auto it = done_.find(derived); it != done_.end()) return it->second;
  // A search over the derived facts below this one; a finished one's support
  // is taken whole.
  std::set<FactId> basic;
  std::vector<NumericVarId> variables;
  std::set<FactId> seen{derived};
  std::vector<FactId> open{derived};
  while (!open.empty()) {
    const FactId d = open.back();
    open.pop_back();
    if (d != derived) {
      if (auto it = done_.find(d); it != done_.end()) {
        basic.insert(it->second.facts.begin(), it->second.facts.end());
        variables.insert(variables.end(), it->second.variables.begin(), it->second.variables.end());
        continue;
      }
    }
    const auto rules = by_head_.find(d);
    if (rules == by_head_.end()) continue;
    for (std::uint32_t x : rules->second) {
      std::vector<FactId> reads;
      append_reads(task_.axioms[x].body, reads, variables);
      for (FactId f : reads) {
        if (!by_head_.count(f)) {
          basic.insert(f);
        } else if (seen.insert(f).second) {
          open.push_back(f);
        }
      }
    }
  }
  Support& s = done_[derived];
  s.facts.assign(basic.begin(), basic.end());
  std::sort(variables.begin(), variables.end());
  variables.erase(std::unique(variables.begin(), variables.end()), variables.end());
  s.variables = std::move(variables);
  return s;
}

}  // namespace alplan
