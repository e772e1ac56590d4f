// The effects of one happening, worked out before any is applied: each
// member's effects are read in the state before the happening (conditions
// of conditional effects, right-hand sides, forall instances), claimed in
// the Ownership table in VAL's order, and recorded. Then all deletes, all
// adds (an add wins over a delete of the same fact by the same member, the
// only way both can meet) and the numeric updates in the order recorded
// are applied (Fox & Long 2003, definition 8: a happening's effects take
// place together, on the state before it).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "oracle/action_parts.h"
#include "oracle/evaluate.h"
#include "oracle/ownership.h"

namespace alplan::oracle {

struct NumericUpdate {
  int fluent = 0;
  pddl::AssignOperator op = pddl::AssignOperator::Assign;
  double amount = 0.0;
};

struct HappeningChanges {
  std::vector<int> deletes, adds;
  std::vector<NumericUpdate> updates;
  // Applies the changes to `state` (derived atoms are left to the caller).
  void apply_to(State& state) const;
};

// The effects of one member. `decided` answers a conditional effect decided
// at the start (action_parts.h, DeferredWhen); null where there is none.
class EffectRecorder {
 public:
  struct Context {
    World& world;
    const State& before;
    Ownership& ownership;
    int member;
    bool claim_condition_reads;  // VAL claims a firing condition's reads only with two members or more
    Comparisons comparisons;
    std::optional<double> duration;
    double time;  // the happening's, for (total-time) read by an effect
    const std::map<const pddl::Effect*, bool>* decided = nullptr;
  };

  EffectRecorder(Context context, HappeningChanges& changes) : c_(context), changes_(changes) {}

  // False at the first claim refused; `refused()` names it.
  bool record(const ActionPart::Effects& effects, Moment moment, Binding& binding);
  const std::string& refused() const { return refused_; }

 private:
  bool when(const ActionPart::Item& item, Moment moment, Binding& binding);
  bool numeric(const pddl::Effect& effect, Binding& binding);
  bool forall(const ActionPart::Item& item, Moment moment, Binding& binding);
  bool refuse(const std::string& what);

  Context c_;
  HappeningChanges& changes_;
  std::string refused_;
};

}  // namespace alplan::oracle
