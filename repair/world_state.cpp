#include "repair/world_state.h"

#include <cctype>

#include "planner/continuous_change.h"
#include "planner/formula_evaluation.h"
#include "planner/happening_effects.h"

namespace alplan::repair {

AtomKey key_of(const pddl::Atom& atom) {
  AtomKey key{atom.name};
  for (const pddl::Term& t : atom.args) key.push_back(t.name);
  return key;
}

bool same_literal(const pddl::TimedInitialLiteral& a, const pddl::TimedInitialLiteral& b) {
  return a.time == b.time && a.positive == b.positive && key_of(a.atom) == key_of(b.atom);
}

pddl::Atom atom_of(const AtomKey& key) {
  pddl::Atom atom;
  atom.name = key.front();
  for (std::size_t i = 1; i < key.size(); ++i) {
    pddl::Term t;
    t.name = key[i];
    atom.args.push_back(t);
  }
  return atom;
}

std::string to_string(const AtomKey& key) {
  std::string out = "(";
  for (std::size_t i = 0; i < key.size(); ++i) out += (i ? " " : "") + key[i];
  return out + ")";
}

AtomKey words_of(const std::string& text) {
  AtomKey words;
  std::string word;
  for (const char c : text) {
    if (c == '(' || c == ')' || std::isspace(static_cast<unsigned char>(c))) {
      if (!word.empty()) words.push_back(std::move(word));
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(std::move(word));
  return words;
}

StateMapping::StateMapping(const GroundTask& task) : task_(&task) {
  const NormalizedTask& lifted = *task.lifted;
  for (FactId f = 0; f < task.facts.size(); ++f) {
    const GroundKey& k = task.facts.key(f);
    AtomKey key{lifted.predicates[k.head].name};
    for (ObjectId o : k.args) key.push_back(lifted.objects[o]);
    fact_keys_.push_back(std::move(key));
  }
  for (NumericVarId v = 0; v < task.numeric.size(); ++v) {
    const GroundKey& k = task.numeric.key(v);
    AtomKey key{lifted.functions[k.head].name};
    for (ObjectId o : k.args) key.push_back(lifted.objects[o]);
    variable_keys_.push_back(std::move(key));
  }
}

ExplicitState StateMapping::to_explicit(const WorldState& world) const {
  ExplicitState state;
  for (FactId f = 0; f < fact_keys_.size(); ++f) {
    if (!task_->is_derived(f)) state.set_fact(f, world.holds(fact_keys_[f]));
  }
  for (NumericVarId v = 0; v < variable_keys_.size(); ++v) {
    auto it = world.values.find(variable_keys_[v]);
    state.set_value(v, it == world.values.end() ? std::nan("") : it->second);
  }
  derive(*task_, state);
  return state;
}

void StateMapping::write_back(const ExplicitState& state, WorldState& world) const {
  for (FactId f = 0; f < fact_keys_.size(); ++f) {
    if (!task_->is_derived(f)) world.set(fact_keys_[f], state.fact(f));
  }
  for (NumericVarId v = 0; v < variable_keys_.size(); ++v) {
    if (!std::isnan(state.value(v))) world.values[variable_keys_[v]] = state.value(v);
  }
}

void apply_snap_effects(const GroundTask& task, ActionId action, bool start, double duration, WorldState& world) {
  const StateMapping mapping(task);
  ExplicitState state = mapping.to_explicit(world);
  EvaluationContext context;
  context.duration = duration;
  const GroundAction& a = task.actions[action];
  apply_happening(task, start ? a.start : a.end, state, context);
  mapping.write_back(state, world);
}

std::vector<std::pair<AtomKey, double>> continuous_rates(const GroundTask& task, ActionId action, double duration,
                                                         const WorldState& world) {
  const GroundAction& a = task.actions[action];
  std::vector<std::pair<AtomKey, double>> rates;
  if (a.continuous.empty()) return rates;
  const StateMapping mapping(task);
  for (const auto& [v, rate] : signed_rates(a, mapping.to_explicit(world), duration)) {
    rates.emplace_back(mapping.variable_key(v), rate);
  }
  return rates;
}

}  // namespace alplan::repair
