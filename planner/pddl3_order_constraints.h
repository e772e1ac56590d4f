// The PDDL 3 operators that judge the order of states (Gerevini & Long
// 2005): at-most-once, sometime-before, sometime-after, hold-during and
// hold-after, compiled into the task the search plans with by monitor facts
// that the task's own snaps keep, after Edelkamp's compilation of plan
// constraints (ICAPS 2006) and the automata of Baier & McIlraith (2006)
// written out as facts. Helpers of pddl3_compilation.cpp, which calls them
// for the hard constraints and the preferences a round enforces.
//
// φ below is a fact or a disjunction of facts (an `exists` over fluent
// atoms grounds to one): "φ becomes true" is then "a snap adds one of them",
// which a precondition can forbid. Other forms of φ are refused by name.
//
// - (at-most-once φ): a fact `closed` that a snap adds when it deletes the
//   last true fact of φ (a conditional effect reading the state before it);
//   each snap that adds a fact of φ needs `closed` false. Exact: once φ has
//   held and stopped, only an adder could make it true again, and every
//   adder needs `closed` false; while φ holds `closed` is false, so no
//   adder is held back then.
// - (sometime-before φ ψ): a witness reading ψ adds `seen`; each snap that
//   adds a fact of φ needs `seen`. The witness comes after ψ's last writer
//   and before the adder, so ψ held in an earlier state of the plan. φ true
//   at first breaks the constraint in the first state.
// - (sometime-after φ ψ): every snap made where φ holds, and every adder of
//   a fact of φ, adds `pending`; a witness reading ψ deletes it; the goal
//   asks `pending` false and, for the final state, φ false or ψ true.
//   Stricter than VAL: a state with φ and ψ that the witness saw is marked
//   again by the next snap, which then needs another witness.
// - (hold-during t1 t2 φ), (hold-after t φ): a timed literal adds `during`
//   at t1 (t) and one deletes it at t2; a hard `always` asks φ or not
//   `during` (the search checks it in every state, the timed literals'
//   included). Stricter than VAL, which reads no state at t1 unless a
//   happening is there, and none at t for hold-after.
//
// The search sees the snaps of one happening one after another, where VAL
// sees the happening's state alone; a fact of φ deleted by one snap and added
// by another at the same time closes φ for the search, not for VAL. Every
// compilation here is therefore recorded as an approximation (a search of
// the compiled task that exhausts proves nothing, search_pipeline.h's
// proof_limits), and every plan is validated on the original task.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "planner/ground_task.h"

namespace alplan {

// The facts of φ when it is one fact or a disjunction of facts, none when
// it can never hold; nullopt for any other form.
std::optional<std::vector<FactId>> fact_disjunction(const ConditionSet& phi);

// Adds a timed literal to the task, keeping its literals sorted by time
// (after those already at that time).
void insert_timed_literal(GroundTask& task, GroundTimedLiteral literal);

// What an order compilation needs of the task being compiled.
struct OrderCompilation {
  GroundTask& task;                // the compiled task, being written
  std::size_t source_actions = 0;  // its first actions are the original task's
  const std::vector<FactId>& start_facts;
  std::function<FactId(const std::string&)> new_fact;
  // A witness: an instantaneous action, one per disjunct of `condition`,
  // that adds the fact (deletes it, where `deletes`); named after constraint k.
  std::function<void(std::size_t k, const ConditionSet& condition, FactId adds, bool deletes)> witness;
};

// Each returns why it cannot compile the constraint, or nullopt when done.
std::optional<std::string> compile_at_most_once(OrderCompilation& c, std::size_t k, const GroundConstraint& g);
std::optional<std::string> compile_sometime_before(OrderCompilation& c, std::size_t k, const GroundConstraint& g);
std::optional<std::string> compile_sometime_after(OrderCompilation& c, std::size_t k, const GroundConstraint& g);
std::optional<std::string> compile_hold(OrderCompilation& c, std::size_t k, const GroundConstraint& g);

}  // namespace alplan
