#include "planner/blind_heuristic.h"

namespace alplan {

HeuristicValue BlindHeuristic::evaluate(const SearchState& state, const PartialPlan& plan, Relaxation) {
  HeuristicValue value;
  bool holds = state.running().empty();
  for (FactId f : index_.task().goal.positive) holds = holds && state.fact(f);
  for (FactId f : index_.task().goal.negative) holds = holds && !state.fact(f);
  value.h = holds ? 0.0 : 1.0;
  value.relaxed_makespan = plan.makespan();
  return value;
}

}  // namespace alplan
