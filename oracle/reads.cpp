#include "oracle/reads.h"

namespace alplan::oracle {

bool ReadClaims::formula(const pddl::Condition& c, Binding& binding) {
  using K = pddl::Condition::Kind;
  switch (c.kind) {
    case K::Atom: {
      const GroundName g = ground(c.atom, binding);
      if (world_.is_derived(c.atom.name)) return derived_atom(g);
      if (ownership_.read_fact(member_, world_.atoms().id(g))) return true;
      refused_ = to_string(g);
      return false;
    }
    case K::Comparison:
      return expression(c.expressions[0], binding) && expression(c.expressions[1], binding);
    case K::Exists:
    case K::Forall: {
      // Every instance, over every object of each variable's type.
      std::vector<std::vector<std::string>> domains;
      for (const pddl::TypedName& v : c.variables) domains.push_back(world_.objects_of(v.types));
      std::vector<std::size_t> index(domains.size(), 0);
      for (const auto& d : domains) {
        if (d.empty()) return true;
      }
      while (true) {
        for (std::size_t k = 0; k < domains.size(); ++k) binding.push(c.variables[k].name, domains[k][index[k]]);
        const bool ok = formula(c.children.front(), binding);
        binding.pop(domains.size());
        if (!ok) return false;
        std::size_t k = 0;
        while (k < domains.size() && ++index[k] == domains[k].size()) index[k++] = 0;
        if (k == domains.size()) return true;
      }
    }
    default:
      for (const pddl::Condition& child : c.children) {
        if (!formula(child, binding)) return false;
      }
      return true;
  }
}

bool ReadClaims::derived_atom(const GroundName& atom) {
  if (!derived_seen_.insert(atom).second) return true;  // each derived atom once per member
  for (const pddl::DerivedPredicate* rule : world_.derived_rules(atom.name)) {
    Binding binding;
    for (std::size_t k = 0; k < rule->parameters.size(); ++k) binding.push(rule->parameters[k].name, atom.args[k]);
    if (!formula(rule->body, binding)) return false;
  }
  return true;
}

bool ReadClaims::expression(const pddl::NumericExpression& e, const Binding& binding) {
  if (e.kind == pddl::NumericExpression::Kind::Function) {
    const GroundName g = ground(e.function, binding);
    if (ownership_.read_fluent(member_, world_.fluents().id(g))) return true;
    refused_ = to_string(g);
    return false;
  }
  for (const pddl::NumericExpression& o : e.operands) {
    if (!expression(o, binding)) return false;
  }
  return true;
}

}  // namespace alplan::oracle
