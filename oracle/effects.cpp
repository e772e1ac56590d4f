#include "oracle/effects.h"

#include "oracle/reads.h"
#include "pddl_parser/writer.h"

namespace alplan::oracle {

void HappeningChanges::apply_to(State& state) const {
  for (int atom : deletes) state.set(atom, false);
  for (int atom : adds) state.set(atom, true);
  for (const NumericUpdate& u : updates) {
    // An update of a fluent with no value starts from 0, as VAL's does.
    const double old = state.value(u.fluent).value_or(0.0);
    switch (u.op) {
      case pddl::AssignOperator::Assign: state.assign(u.fluent, u.amount); break;
      case pddl::AssignOperator::Increase: state.assign(u.fluent, old + u.amount); break;
      case pddl::AssignOperator::Decrease: state.assign(u.fluent, old - u.amount); break;
      case pddl::AssignOperator::ScaleUp: state.assign(u.fluent, old * u.amount); break;
      case pddl::AssignOperator::ScaleDown: state.assign(u.fluent, old / u.amount); break;
    }
  }
}

bool EffectRecorder::refuse(const std::string& what) {
  refused_ = what;
  return false;
}

bool EffectRecorder::record(const ActionPart::Effects& effects, Moment moment, Binding& binding) {
  for (const ActionPart::Item& item : effects.adds) {
    const GroundName g = ground(item.node->atom, binding);
    const int id = c_.world.atoms().id(g);
    if (!c_.ownership.add_fact(c_.member, id)) return refuse("adds " + to_string(g));
    changes_.adds.push_back(id);
  }
  for (const ActionPart::Item& item : effects.deletes) {
    const GroundName g = ground(item.node->atom, binding);
    const int id = c_.world.atoms().id(g);
    if (!c_.ownership.delete_fact(c_.member, id)) return refuse("deletes " + to_string(g));
    changes_.deletes.push_back(id);
  }
  for (const ActionPart::Item& item : effects.whens) {
    if (!when(item, moment, binding)) return false;
  }
  for (const ActionPart::Item& item : effects.numerics) {
    if (!numeric(*item.node, binding)) return false;
  }
  for (const ActionPart::Item& item : effects.foralls) {
    if (!forall(item, moment, binding)) return false;
  }
  return true;
}

bool EffectRecorder::when(const ActionPart::Item& item, Moment moment, Binding& binding) {
  const pddl::Effect& e = *item.node;
  bool fires = false;
  const pddl::Condition* read = &*e.condition;
  std::optional<pddl::Condition> part;
  if (c_.decided && c_.decided->count(&e)) {
    fires = c_.decided->at(&e);
    read = nullptr;  // its reads were claimed at the start
  } else {
    if (e.condition->kind == pddl::Condition::Kind::Timed ||
        (e.condition->kind == pddl::Condition::Kind::And && !e.condition->children.empty() &&
         e.condition->children.front().kind == pddl::Condition::Kind::Timed)) {
      // (when (at end c) (at end e)): the condition's part at this moment.
      pddl::Condition conjunction;
      for (const pddl::Condition& c : e.condition->kind == pddl::Condition::Kind::And
                                          ? e.condition->children
                                          : std::vector<pddl::Condition>{*e.condition}) {
        if (c.kind == pddl::Condition::Kind::Timed) conjunction.children.push_back(c.children.front());
      }
      part = std::move(conjunction);
      read = &*part;
    }
    Scope scope(c_.world, c_.before, binding, c_.comparisons);
    scope.duration = c_.duration;
    scope.total_time = c_.time;
    fires = holds(*read, scope);
  }
  if (!fires) return true;
  if (read && c_.claim_condition_reads) {
    ReadClaims claims(c_.world, c_.ownership, c_.member);
    if (!claims.formula(*read, binding)) return refuse("reads " + claims.refused() + " in a conditional effect");
  }
  return record(bucket_effects(e.children.front(), moment, item.above), moment, binding);
}

bool EffectRecorder::numeric(const pddl::Effect& e, Binding& binding) {
  ReadClaims claims(c_.world, c_.ownership, c_.member);
  if (!claims.expression(*e.value, binding)) return refuse("reads " + claims.refused());
  const GroundName target = ground(e.atom, binding);
  const int id = c_.world.fluents().id(target);
  const bool additive = e.assign == pddl::AssignOperator::Increase || e.assign == pddl::AssignOperator::Decrease;
  if (!c_.ownership.write_fluent(c_.member, id, additive)) return refuse("changes " + to_string(target));
  Scope scope(c_.world, c_.before, binding, c_.comparisons);
  scope.duration = c_.duration;
  scope.total_time = c_.time;
  changes_.updates.push_back({id, e.assign, value(*e.value, scope)});
  return true;
}

bool EffectRecorder::forall(const ActionPart::Item& item, Moment moment, Binding& binding) {
  const pddl::Effect& e = *item.node;
  std::vector<std::vector<std::string>> domains;
  for (const pddl::TypedName& v : e.variables) domains.push_back(c_.world.objects_of(v.types));
  for (const auto& d : domains) {
    if (d.empty()) return true;
  }
  const ActionPart::Effects body = bucket_effects(e.children.front(), moment, item.above);
  std::vector<std::size_t> index(domains.size(), 0);
  while (true) {
    for (std::size_t k = 0; k < domains.size(); ++k) binding.push(e.variables[k].name, domains[k][index[k]]);
    const bool ok = record(body, moment, binding);
    binding.pop(domains.size());
    if (!ok) return false;
    std::size_t k = 0;
    while (k < domains.size() && ++index[k] == domains[k].size()) index[k++] = 0;
    if (k == domains.size()) return true;
  }
}

}  // namespace alplan::oracle
