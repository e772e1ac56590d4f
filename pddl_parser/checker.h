// Semantic checks of a parsed domain and problem. Every finding names the
// place (file:line:col) and says what was expected and what was found; all of
// a file's findings are collected, not only the first.
//
// Errors: unknown requirement; undefined type, predicate, function, object,
// constant or variable; wrong arity; wrong argument type; duplicate
// definitions; cyclic types; a construct where PDDL does not allow it (a timed
// condition in a goal, an untimed condition in a durative action, ?duration
// outside a durative action, an effect on a derived predicate); a timed
// initial literal on something that is not a fluent literal (a derived
// predicate or a numeric function); a durative action without a ?duration
// constraint.
// Warnings: a construct used without its :requirements flag (several IPC
// domains omit flags; VAL accepts them too), once per flag at its first use
// (durative actions, numeric fluents, negative, disjunctive, quantified
// and equality conditions, conditional effects, types, derived predicates,
// preferences, constraints); objects that repeat constants.
#pragma once

#include <vector>

#include "pddl_parser/ast.h"
#include "pddl_parser/source_location.h"

namespace alplan::pddl {

std::vector<Diagnostic> check_domain(const Domain& domain, const std::string& file_name);
std::vector<Diagnostic> check_problem(const Domain& domain, const Problem& problem,
                                      const std::string& file_name);

// The requirement flags of PDDL 1.2, 2.1, 2.2, 3.0 and 3.1.
bool is_known_requirement(const std::string& name);

}  // namespace alplan::pddl
