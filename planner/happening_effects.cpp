#include "planner/happening_effects.h"

#include <cmath>
#include <utility>

namespace alplan {

double updated_value(double current, pddl::AssignOperator op, double value) {
  if (std::isnan(current)) current = 0.0;
  switch (op) {
    case pddl::AssignOperator::Assign: return value;
    case pddl::AssignOperator::Increase: return current + value;
    case pddl::AssignOperator::Decrease: return current - value;
    case pddl::AssignOperator::ScaleUp: return current * value;
    case pddl::AssignOperator::ScaleDown: return current / value;
  }
  return value;
}

void apply_happening(const GroundTask& task, const HappeningEffects& effects, ExplicitState& state,
                     const EvaluationContext& context) {
  std::vector<FactId> adds, dels;
  std::vector<std::pair<const NumericAssignment*, double>> updates;
  auto collect = [&](const std::vector<FactId>& a, const std::vector<FactId>& d,
                     const std::vector<NumericAssignment>& numeric) {
    adds.insert(adds.end(), a.begin(), a.end());
    dels.insert(dels.end(), d.begin(), d.end());
    for (const NumericAssignment& n : numeric) updates.emplace_back(&n, evaluate(n.value, state, context));
  };
  collect(effects.add, effects.del, effects.numeric);
  for (const ConditionalEffect& c : effects.conditional) {
    if (holds(c.condition, state, context, kNumericSlack)) collect(c.add, c.del, c.numeric);
  }
  for (FactId f : dels) state.set_fact(f, false);
  for (FactId f : adds) state.set_fact(f, true);
  for (const auto& [n, value] : updates) {
    state.set_value(n->variable, updated_value(state.value(n->variable), n->assign, value));
  }
  derive(task, state);
}

}  // namespace alplan
