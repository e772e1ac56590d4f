#include "benchmarks/harness/perturbation.h"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace alplan::bench {
namespace {

using repair::AtomKey;

template <typename T>
const T& pick(const std::vector<T>& items, std::mt19937_64& random) {
  return items[std::uniform_int_distribution<std::size_t>(0, items.size() - 1)(random)];
}

std::vector<const repair::ScheduledAction*> remaining_steps(const PerturbationContext& c) {
  std::vector<const repair::ScheduledAction*> steps;
  for (const repair::ScheduledAction& s : c.plan->steps) {
    if (s.start + 1e-9 >= c.now) steps.push_back(&s);
  }
  return steps;
}

bool mentions(const AtomKey& key, const std::string& object) {
  return std::find(key.begin() + 1, key.end(), object) != key.end();
}

// The facts the state holds that some remaining step needs (its start, over
// all and end conditions, positive ones), sorted: a draw depends on the seed
// alone, not on the order of a hash table.
std::vector<AtomKey> needed_facts(const PerturbationContext& c) {
  const GroundTask& task = *c.plan->task;
  const repair::StateMapping mapping(task);
  std::set<AtomKey> needed;
  for (const repair::ScheduledAction* s : remaining_steps(c)) {
    const GroundAction& a = task.actions[s->action];
    for (const ConditionSet* set : {&a.at_start, &a.over_all, &a.at_end}) {
      for (FactId f : set->positive) {
        if (c.state->holds(mapping.fact_key(f))) needed.insert(mapping.fact_key(f));
      }
    }
  }
  return {needed.begin(), needed.end()};
}

// Reachable facts that differ from `fact` in the last argument alone and do
// not hold now: where a thing at one place may be instead.
std::vector<AtomKey> relocations(const PerturbationContext& c, const AtomKey& fact) {
  std::vector<AtomKey> moves;
  if (fact.size() < 3) return moves;
  const repair::StateMapping mapping(*c.reachable);
  for (FactId f = 0; f < c.reachable->facts.size(); ++f) {
    const AtomKey& other = mapping.fact_key(f);
    if (other.size() != fact.size() || other.back() == fact.back() || c.state->holds(other)) continue;
    if (std::equal(fact.begin(), fact.end() - 1, other.begin())) moves.push_back(other);
  }
  std::sort(moves.begin(), moves.end());
  return moves;
}

std::optional<Perturbation> draw_fact(const PerturbationContext& c, std::mt19937_64& random) {
  const std::vector<AtomKey> needed = needed_facts(c);
  if (needed.empty()) return std::nullopt;
  Perturbation p;
  p.kind = PerturbationKind::Fact;
  const AtomKey& gone = pick(needed, random);
  p.changes.push_back({gone, false});
  p.description = repair::to_string(gone) + " became false";
  const std::vector<AtomKey> moves = relocations(c, gone);
  if (!moves.empty()) {
    const AtomKey& instead = pick(moves, random);
    p.changes.push_back({instead, true});
    p.description += ", " + repair::to_string(instead) + " true";
  }
  return p;
}

// The predicates some action changes: an object's facts of these are its
// state (where it is, what it holds); the others are the map.
std::set<std::string> fluent_heads(const GroundTask& task) {
  const repair::StateMapping mapping(task);
  std::set<std::string> heads;
  for (const GroundAction& a : task.actions) {
    for (const HappeningEffects* e : {&a.start, &a.end}) {
      for (FactId f : e->add) heads.insert(mapping.fact_key(f).front());
      for (FactId f : e->del) heads.insert(mapping.fact_key(f).front());
    }
  }
  return heads;
}

std::optional<Perturbation> draw_object(const PerturbationContext& c, std::mt19937_64& random) {
  const GroundTask& task = *c.plan->task;
  const std::set<std::string> fluent = fluent_heads(task);
  std::set<std::string> candidates;
  for (const repair::ScheduledAction* s : remaining_steps(c)) {
    for (ObjectId o : task.actions[s->action].args) candidates.insert(task.lifted->objects[o]);
  }
  const auto in_goal = [&](const std::string& o) {
    return std::any_of(c.goals.begin(), c.goals.end(), [&](const AtomKey& g) { return mentions(g, o); });
  };
  // A thing is lost, not a place: it must have a state of its own (a fluent
  // fact with it first), and nothing a goal names may go with it (a package
  // in a lost truck would make the goal unreachable for every strategy).
  std::erase_if(candidates, [&](const std::string& o) {
    bool has_state = false, carries_goal_object = false;
    for (const AtomKey& a : c.state->atoms) {
      if (!fluent.count(a.front()) || !mentions(a, o)) continue;
      has_state = has_state || a[1] == o;
      carries_goal_object = carries_goal_object ||
                            std::any_of(a.begin() + 1, a.end(), [&](const std::string& x) { return x != o && in_goal(x); });
    }
    return !has_state || carries_goal_object || in_goal(o) ||
           std::find(c.busy.begin(), c.busy.end(), o) != c.busy.end();
  });
  if (candidates.empty()) return std::nullopt;
  const std::vector<std::string> sorted(candidates.begin(), candidates.end());
  const std::string lost = pick(sorted, random);
  Perturbation p;
  p.kind = PerturbationKind::Object;
  for (const AtomKey& a : c.state->atoms) {
    if (fluent.count(a.front()) && mentions(a, lost)) p.changes.push_back({a, false});
  }
  p.description = lost + " is lost: " + std::to_string(p.changes.size()) + " facts about it became false";
  return p;
}

std::optional<Perturbation> draw_goal(const PerturbationContext& c, std::mt19937_64& random) {
  std::set<std::string> heads, placed;
  for (const AtomKey& g : c.goals) {
    heads.insert(g.front());
    if (g.size() > 1) placed.insert(g[1]);
  }
  const repair::StateMapping mapping(*c.reachable);
  std::vector<AtomKey> candidates;
  for (FactId f = 0; f < c.reachable->facts.size(); ++f) {
    const AtomKey& fact = mapping.fact_key(f);
    if (fact.size() < 2 || !heads.count(fact.front()) || placed.count(fact[1]) || c.state->holds(fact)) continue;
    candidates.push_back(fact);
  }
  if (candidates.empty()) return std::nullopt;
  std::sort(candidates.begin(), candidates.end());
  Perturbation p;
  p.kind = PerturbationKind::Goal;
  p.added_goals.push_back(pick(candidates, random));
  p.description = "goal " + repair::to_string(p.added_goals.front()) + " added";
  return p;
}

void collect_goal_atoms(const pddl::Condition& c, std::vector<AtomKey>& out) {
  if (c.kind == pddl::Condition::Kind::Atom) {
    out.push_back(repair::key_of(c.atom));
  } else if (c.kind == pddl::Condition::Kind::And) {
    for (const pddl::Condition& child : c.children) collect_goal_atoms(child, out);
  } else {
    throw std::invalid_argument("the testbed needs goals that are conjunctions of atoms");
  }
}

}  // namespace

const char* to_string(PerturbationKind kind) {
  switch (kind) {
    case PerturbationKind::Fact: return "fact";
    case PerturbationKind::Object: return "object";
    case PerturbationKind::Goal: return "goal";
  }
  return "?";
}

std::optional<PerturbationKind> perturbation_kind(const std::string& name) {
  for (PerturbationKind k : {PerturbationKind::Fact, PerturbationKind::Object, PerturbationKind::Goal}) {
    if (name == to_string(k)) return k;
  }
  return std::nullopt;
}

std::optional<Perturbation> draw_perturbation(PerturbationKind kind, const PerturbationContext& context,
                                              std::mt19937_64& random) {
  switch (kind) {
    case PerturbationKind::Fact: return draw_fact(context, random);
    case PerturbationKind::Object: return draw_object(context, random);
    case PerturbationKind::Goal: return draw_goal(context, random);
  }
  return std::nullopt;
}

std::vector<AtomKey> goal_atoms(const pddl::Problem& problem) {
  std::vector<AtomKey> atoms;
  if (problem.goal) collect_goal_atoms(*problem.goal, atoms);
  return atoms;
}

pddl::Problem with_goals(const pddl::Problem& problem, const std::vector<AtomKey>& added) {
  pddl::Problem out = problem;
  if (added.empty()) return out;
  pddl::Condition conjunction;
  conjunction.kind = pddl::Condition::Kind::And;
  if (out.goal) conjunction.children.push_back(*out.goal);
  for (const AtomKey& key : added) {
    pddl::Condition atom;
    atom.kind = pddl::Condition::Kind::Atom;
    atom.atom = repair::atom_of(key);
    conjunction.children.push_back(atom);
  }
  out.goal = conjunction;
  return out;
}

}  // namespace alplan::bench
