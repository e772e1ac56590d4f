// What each part of an action is made of: an instantaneous action is one
// part; a durative action (PDDL 2.1, Fox & Long 2003, section 8) is a start
// and an end, each with its conditions, duration constraints and effects,
// and an invariant (its over-all conditions) held on the open interval
// between them.
//
// The parts are copies of the AST's sub-trees with the time specifiers taken
// off: `(at start φ)` becomes φ in the start's list, `(preference p (at end
// φ))` becomes `(preference p φ)` in the end's. A condition outside every
// time specifier is not PDDL 2.1 (VAL stops on it), so it is not judged.
#pragma once

#include <optional>
#include <vector>

#include "oracle/world.h"
#include "pddl_parser/ast.h"

namespace alplan::oracle {

enum class Moment : unsigned char { Instant, Start, End };

// A conditional effect of a durative action whose condition is read at the
// start (and, over all, while it runs) but whose effect comes at the end
// (VAL's CondCommunicationAction). Its at-end part is never read, as in VAL.
struct DeferredWhen {
  const pddl::Effect* node = nullptr;  // the when, for matching start and end
  std::optional<pddl::Condition> at_start, over_all;
};

struct ActionPart {
  std::vector<pddl::Condition> conditions;
  std::vector<pddl::DurationConstraint> durations;
  // The effects of this part in the order VAL processes them (VAL's
  // effect_lists: adds, deletes, conditional effects, numeric effects,
  // quantified effects), each a sub-tree of the action's effect.
  struct Item {
    const pddl::Effect* node = nullptr;
    std::optional<Moment> above;  // the time specifier above the node, if any
  };
  struct Effects {
    std::vector<Item> adds, deletes, whens, numerics, foralls;
  } effects;
};

struct ActionParts {
  bool durative = false;
  ActionPart instant;      // an instantaneous action
  ActionPart start, end;   // a durative action
  std::vector<pddl::Condition> invariant;  // over all
  std::vector<DeferredWhen> deferred;      // conditional effects decided at the start
};

ActionParts parts_of(const pddl::Action& action);
ActionParts parts_of(const pddl::DurativeAction& action);

// Buckets one effect list (VAL's order); `moment` keeps only what happens
// then (Instant: everything). Used for the parts and for the inside of a
// conditional or quantified effect.
ActionPart::Effects bucket_effects(const pddl::Effect& effect, Moment moment,
                                  std::optional<Moment> above = std::nullopt);

}  // namespace alplan::oracle
