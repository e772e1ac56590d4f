// Prints the AST as canonical PDDL: lower-case, sections in a fixed order,
// one conjunct per line at the top of conditions and effects, numbers in the
// shortest decimal form that reads back to the same double.
//
// Contract: for every AST `a` the parser produced, parse(write(a)) == a
// (tested on every IPC file).
#pragma once

#include <string>

#include "pddl_parser/ast.h"

namespace alplan::pddl {

std::string write_domain(const Domain& domain);
std::string write_problem(const Problem& problem);

// One-line forms, for messages and violation records.
std::string write_condition(const Condition& condition);
std::string write_effect(const Effect& effect);
std::string write_atom(const Atom& atom);
std::string write_expression(const NumericExpression& expression);
std::string write_type(const TypeNames& types);

// Shortest fixed-point text that parses back to exactly `value`.
std::string format_number(double value);

}  // namespace alplan::pddl
