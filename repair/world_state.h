// The world as the monitor observes it, in PDDL terms (names, not ids): the
// planner's ids change whenever a repair re-grounds the task (new objects),
// while what is true of the world does not. StateMapping translates between
// this and the ExplicitState of one grounded task.
#pragma once

#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "pddl_parser/ast.h"
#include "planner/explicit_state.h"
#include "planner/ground_task.h"

namespace alplan::repair {

// A ground atom or function term: the head, then the arguments, lower-case.
using AtomKey = std::vector<std::string>;

// The key of a ground atom of the parser's AST.
AtomKey key_of(const pddl::Atom& atom);
// The same literal at the same time, wherever each was written.
bool same_literal(const pddl::TimedInitialLiteral& a, const pddl::TimedInitialLiteral& b);

std::string to_string(const AtomKey& key);  // "(be robot1 kitchen1)"
// The words of a ground atom or action as written, parentheses dropped:
// "(be senior1 room2)" gives {"be", "senior1", "room2"}.
AtomKey words_of(const std::string& text);
// The atom (or function term) a key names, as the parser's AST holds it.
pddl::Atom atom_of(const AtomKey& key);

struct WorldState {
  double time = 0.0;
  std::set<AtomKey> atoms;
  std::map<AtomKey, double> values;

  bool holds(const AtomKey& atom) const { return atoms.count(atom) != 0; }
  void set(const AtomKey& atom, bool on) { on ? void(atoms.insert(atom)) : void(atoms.erase(atom)); }
};

// The translation for one grounded task. Facts the task does not know (it
// grounded them away as static or unreachable) are left alone in the world.
class StateMapping {
 public:
  explicit StateMapping(const GroundTask& task);

  ExplicitState to_explicit(const WorldState& world) const;
  // Writes every fact and variable the task knows back into the world.
  void write_back(const ExplicitState& state, WorldState& world) const;

  const AtomKey& fact_key(FactId f) const { return fact_keys_[f]; }
  const AtomKey& variable_key(NumericVarId v) const { return variable_keys_[v]; }
  const GroundTask& task() const { return *task_; }

 private:
  const GroundTask* task_;
  std::vector<AtomKey> fact_keys_, variable_keys_;
};

// Applies a snap's effects (the start's or the end's) of one of the task's
// actions to the world, as the task's semantics say.
void apply_snap_effects(const GroundTask& task, ActionId action, bool start, double duration, WorldState& world);

// The rates of an action's continuous effects, as it starts in `world`
// (before its start's effects, as the validator fixes them): the value each
// moves and its change per second, negative for a decrease. Empty for an
// action without continuous change. Throws EvaluationError on a rate the
// world has no value for.
std::vector<std::pair<AtomKey, double>> continuous_rates(const GroundTask& task, ActionId action, double duration,
                                                         const WorldState& world);

}  // namespace alplan::repair
