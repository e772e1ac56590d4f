// Sapa's resource adjustment (Do & Kambhampati, "Sapa: A Multi-objective
// Metric Temporal Planner", JAIR 20, 2003, section 4.3) for linear
// continuous change. The temporal RPG relaxes numeric change to interval
// bounds: once one producer (a recharge, a refuel) is reachable, the
// variable is unbounded above, so the relaxed plan never counts what its
// consumers (moves draining a battery, a generator burning fuel) use up, and
// the second and third recharges are left for the search to find.
//
// After the relaxed plan is extracted, this balances each changing variable
// that a condition of the relaxed plan, of a running action or of the goal
// bounds from below:
//   shortfall = highest lower bound asked + what the relaxed plan's actions
//               and the running actions consume - the greatest value now
//               - what the relaxed plan's and running producers give,
// and a shortfall costs ceil(shortfall / the most one producer can give)
// applications of a producer. The heuristic adds the cheapest producer to
// the relaxed plan with what it needs (the moves to a dock) and counts the
// further applications bare. What one producer gives is its rate times its longest
// duration (a duration bounded by the variable itself, "charge until full",
// taken from the least level the plan asks for), capped by its own
// over-all upper bound on the variable. Both are optimistic, so the count
// is a floor on the producers a real plan needs, not a proof that it needs
// them: a shortfall never makes a dead end. Variables that conditions bound
// from above (a tank that must not overflow) are not balanced.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "planner/continuous_change.h"
#include "planner/ground_task.h"
#include "planner/partial_plan.h"
#include "planner/search_state.h"

namespace alplan {

struct ResourceShortfall {
  NumericVarId variable = kNoId;
  double amount = 0.0;        // what is missing below the highest lower bound asked
  double applications = 0.0;  // how many applications of the best producer cover it
  std::vector<ActionId> producers;  // the actions that can give some of it (not running ones)
};

// What the balance reads of one evaluation of the heuristic.
struct ShortfallInput {
  const SearchState* state = nullptr;
  const PartialPlan* plan = nullptr;
  std::vector<ActionId> relaxed_starts;           // actions the relaxed plan starts (not running ones)
  std::function<double(ActionId)> min_duration;   // in the state; negative when invalid
  // The greatest value a variable can have now over every schedule the
  // partial plan allows (a recharge already planned may still run longer);
  // asked only where the value in the current schedule falls short.
  std::function<double(NumericVarId)> greatest;
};

// +1 when the conditions bound v only from below (it must not fall), -1
// when only from above, 0 otherwise (both, or read with other variables).
int bound_direction(const std::vector<LinearCondition>& conditions, NumericVarId v);
// +1 when the action can only increase v (continuously or at a snap), -1
// when it can only decrease it, 0 otherwise.
int change_direction(const ContinuousModel& model, const GroundAction& action, NumericVarId v,
                     const SearchState& state);

class ResourceBalance {
 public:
  ResourceBalance(const GroundTask& task, const ContinuousModel& model) : task_(task), model_(model) {}
  std::vector<ResourceShortfall> shortfalls(const ShortfallInput& input) const;

 private:
  struct Account {
    double need = -1e300;   // highest lower bound asked
    double consumed = 0.0;  // by the relaxed plan and running actions
    double produced = 0.0;
    bool asked = false;
  };
  // What an action asks of and does to the changing variables, read once
  // per evaluation: its start's and (durative) its end's continuous parts.
  struct Snaps {
    ActionId action = kNoId;
    bool running = false;
    std::optional<ContinuousStep> start, end;
  };
  Snaps snaps_of(ActionId a, bool running, const SearchState& state) const;
  static void ask(const Snaps& snaps, std::vector<Account>& accounts);
  // What one application adds to v at its snaps, and by its rate (at most
  // its longest duration, from the least level asked); 0 for a decrease.
  static double discrete_gain(const Snaps& snaps, NumericVarId v);
  double continuous_gain(const Snaps& snaps, NumericVarId v, const SearchState& state, double need) const;
  void add_changes(const Snaps& snaps, double duration, const ShortfallInput& input,
                   std::vector<Account>& accounts) const;

  const GroundTask& task_;
  const ContinuousModel& model_;
};

}  // namespace alplan
