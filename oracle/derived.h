// Derived predicates (PDDL 2.2 axioms): the atoms that follow from a state's
// basic atoms and values, as the least fixpoint of the rules taken stratum
// by stratum (Edelkamp & Hoffmann 2004, section 3; Thiebaux, Hoffmann &
// Nebel, "In defense of PDDL axioms", AIJ 168, 2005: a stratified rule set
// has one such model, whatever the order rules are applied in).
//
// A predicate's stratum is above every derived predicate it reads under a
// negation and no lower than those it reads positively; a rule set with no
// such numbering (a negative cycle) is not PDDL 2.2 and is not judged.
#pragma once

#include "oracle/evaluate.h"
#include "oracle/state.h"
#include "oracle/world.h"

namespace alplan::oracle {

// Recomputes the derived atoms of `state` from its basic atoms and values.
void close_derived(World& world, State& state, const Comparisons& comparisons);

}  // namespace alplan::oracle
