// What a member of a happening reads, claimed in the happening's Ownership
// table (ownership.h): every atom a formula mentions (each disjunct, each
// instance of a quantifier, and the body of every derived atom it mentions,
// down to basic atoms) and every fluent its comparisons or expressions
// mention. What is read is what a formula could depend on, not what one
// evaluation happened to look at, as VAL marks it.
#pragma once

#include <set>

#include "oracle/evaluate.h"
#include "oracle/ownership.h"

namespace alplan::oracle {

class ReadClaims {
 public:
  ReadClaims(World& world, Ownership& ownership, int member) : world_(world), ownership_(ownership), member_(member) {}

  // False at the first read refused; `refused` then names it.
  bool formula(const pddl::Condition& condition, Binding& binding);
  bool expression(const pddl::NumericExpression& expression, const Binding& binding);
  const std::string& refused() const { return refused_; }

 private:
  bool derived_atom(const GroundName& atom);

  World& world_;
  Ownership& ownership_;
  int member_;
  std::set<GroundName> derived_seen_;
  std::string refused_;
};

}  // namespace alplan::oracle
