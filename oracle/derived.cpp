#include "oracle/derived.h"

#include <map>
#include <set>

#include "oracle/evaluate.h"

namespace alplan::oracle {
namespace {

using CKind = pddl::Condition::Kind;

// (predicate, read under a negation) for every derived atom a formula reads.
void reads(const World& world, const pddl::Condition& c, bool negated, std::set<std::pair<std::string, bool>>& out) {
  switch (c.kind) {
    case CKind::Atom:
      if (world.is_derived(c.atom.name)) out.insert({c.atom.name, negated});
      return;
    case CKind::Not: reads(world, c.children.front(), !negated, out); return;
    case CKind::Imply:
      reads(world, c.children[0], !negated, out);
      reads(world, c.children[1], negated, out);
      return;
    default:
      for (const pddl::Condition& child : c.children) reads(world, child, negated, out);
  }
}

// Stratum of every derived predicate: the least numbering with
// stratum(p) >= stratum(q) for q read positively, > for q read negatively.
std::map<std::string, int> strata(const World& world) {
  std::map<std::string, std::set<std::pair<std::string, bool>>> depends;
  for (const pddl::DerivedPredicate& d : world.domain().derived_predicates) reads(world, d.body, false, depends[d.name]);
  std::map<std::string, int> stratum;
  for (const auto& [p, unused] : depends) stratum[p] = 0;
  const int limit = static_cast<int>(depends.size());
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [p, deps] : depends) {
      for (const auto& [q, negated] : deps) {
        const int need = stratum[q] + (negated ? 1 : 0);
        if (stratum[p] < need) {
          stratum[p] = need;
          changed = true;
          if (need > limit) throw NotJudged("derived predicates with a negative cycle through " + p);
        }
      }
    }
  }
  return stratum;
}

// Applies every rule of one stratum once to every binding; true when an
// atom was added.
bool apply_rules(World& world, State& state, const std::vector<const pddl::DerivedPredicate*>& rules,
                 const Comparisons& comparisons) {
  bool added = false;
  for (const pddl::DerivedPredicate* rule : rules) {
    Binding binding;
    Scope scope(world, state, binding, comparisons);
    std::vector<std::vector<std::string>> domains;
    for (const pddl::TypedName& p : rule->parameters) domains.push_back(world.objects_of(p.types));
    std::vector<std::size_t> index(domains.size(), 0);
    bool empty = false;
    for (const auto& d : domains) empty = empty || d.empty();
    if (empty) continue;
    while (true) {
      GroundName head{rule->name, {}};
      for (std::size_t k = 0; k < domains.size(); ++k) {
        head.args.push_back(domains[k][index[k]]);
        binding.push(rule->parameters[k].name, domains[k][index[k]]);
      }
      const int id = world.atoms().id(head);
      if (!state.derived_holds(id) && holds(rule->body, scope)) {
        state.set_derived(id, true);
        added = true;
      }
      binding.pop(domains.size());
      std::size_t k = 0;
      while (k < domains.size() && ++index[k] == domains[k].size()) index[k++] = 0;
      if (k == domains.size()) break;
    }
  }
  return added;
}

}  // namespace

void close_derived(World& world, State& state, const Comparisons& comparisons) {
  state.clear_derived();
  if (world.domain().derived_predicates.empty()) return;
  std::map<int, std::vector<const pddl::DerivedPredicate*>> by_stratum;
  const std::map<std::string, int> stratum = strata(world);
  for (const pddl::DerivedPredicate& d : world.domain().derived_predicates) by_stratum[stratum.at(d.name)].push_back(&d);
  for (const auto& [level, rules] : by_stratum) {
    while (apply_rules(world, state, rules, comparisons)) {
    }
  }
}

}  // namespace alplan::oracle
