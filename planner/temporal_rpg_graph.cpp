// The relaxed planning graph's static part (planner/temporal_rpg.h): each
// action's relaxed preconditions and effects and the watchers that wake it,
// built once per task and shared by the heuristics of tasks that share its
// ground actions (a grounding cache's).
#include "planner/temporal_rpg.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "planner/numeric_relaxation.h"
#include "planner/successor_generator.h"

namespace alplan {

bool TemporalRpg::fits(const Graph& graph, const GroundTask& task) {
  const GroundTask& built = *graph.task;
  return same_ground_actions(task, built) && task.goal.positive == built.goal.positive && task.goal.numeric.empty() &&
         built.goal.numeric.empty();
}

std::shared_ptr<const TemporalRpg::Graph> TemporalRpg::build(const TaskIndex& index) {
  const GroundTask& task = index.task();
  auto graph = std::make_shared<Graph>();
  graph->task = index.task_pointer();
  auto add_comparisons = [&](const std::vector<GroundComparison>& comparisons) {
    const auto first = static_cast<std::uint32_t>(graph->comparisons.size());
    for (const GroundComparison& c : comparisons) graph->comparisons.push_back(&c);
    return first;
  };
  const std::size_t facts = task.facts.size();
  graph->start_watchers.resize(facts);
  graph->end_watchers.resize(facts);
  graph->axiom_watchers.resize(facts);
  graph->numeric_watchers.resize(task.numeric.size());
  graph->actions.resize(task.actions.size());
  auto numeric_list = [&](const ConditionSet& c, std::vector<std::uint32_t>& out) {
    const std::uint32_t first = add_comparisons(c.numeric);
    for (std::uint32_t i = 0; i < c.numeric.size(); ++i) out.push_back(first + i);
  };
  auto adds = [&](const HappeningEffects& e, std::vector<FactId>& out, std::vector<const NumericAssignment*>& num) {
    out = e.add;
    for (const NumericAssignment& n : e.numeric) num.push_back(&n);
    for (const ConditionalEffect& c : e.conditional) {
      out.insert(out.end(), c.add.begin(), c.add.end());
      for (const NumericAssignment& n : c.numeric) num.push_back(&n);
    }
  };
  for (ActionId a = 0; a < task.actions.size(); ++a) {
    const GroundAction& g = task.actions[a];
    RelaxedAction& r = graph->actions[a];
    r.durative = g.durative;
    if (const std::optional<DurationWindow> w = constant_duration_window(g, Moment::Start)) {
      r.fixed_duration = w->valid ? w->min : -1.0;
    }
    adds(g.start, r.start_add, r.start_numeric_effects);
    if (g.durative) {
      adds(g.end, r.end_add, r.end_numeric_effects);
      // Only unconditional effects are g.end.numeric's; the adds put them first.
      const std::size_t unconditional = g.end.numeric.size();
      std::vector<const NumericAssignment*> kept;
      for (std::size_t i = 0; i < r.end_numeric_effects.size(); ++i) {
        const NumericAssignment* n = r.end_numeric_effects[i];
        (i < unconditional && give_back(g, *n) ? r.end_returns : kept).push_back(n);
      }
      r.end_numeric_effects = std::move(kept);
    }
    for (const ContinuousEffect& c : g.continuous) {
      graph->continuous_effects.push_back({c.variable, c.assign, c.rate});
      r.start_numeric_effects.push_back(&graph->continuous_effects.back());
      // Once more at the end, for an action already running in the state.
      if (g.durative) r.end_numeric_effects.push_back(&graph->continuous_effects.back());
    }
    r.start_pre = g.at_start.positive;
    numeric_list(g.at_start, r.start_numeric);
    if (g.durative) {
      // An invariant the start establishes itself is not needed before it.
      for (FactId f : g.over_all.positive) {
        if (std::find(r.start_add.begin(), r.start_add.end(), f) == r.start_add.end()) r.start_pre.push_back(f);
      }
      r.end_pre = g.at_end.positive;
      r.end_pre.insert(r.end_pre.end(), g.over_all.positive.begin(), g.over_all.positive.end());
      numeric_list(g.over_all, r.start_numeric);
      numeric_list(g.at_end, r.end_numeric);
    }
    std::sort(r.start_pre.begin(), r.start_pre.end());
    r.start_pre.erase(std::unique(r.start_pre.begin(), r.start_pre.end()), r.start_pre.end());
    std::sort(r.end_pre.begin(), r.end_pre.end());
    r.end_pre.erase(std::unique(r.end_pre.begin(), r.end_pre.end()), r.end_pre.end());
    for (FactId f : r.start_pre) graph->start_watchers[f].push_back(a);
    for (FactId f : r.end_pre) graph->end_watchers[f].push_back(a);
  }
  for (std::uint32_t x = 0; x < task.axioms.size(); ++x) {
    for (FactId f : task.axioms[x].body.positive) graph->axiom_watchers[f].push_back(x);
  }
  graph->goal_facts = task.goal.positive;  // sorted by flatten()
  numeric_list(task.goal, graph->goal_numeric);
  graph->comparison_variables.resize(graph->comparisons.size());
  for (std::uint32_t c = 0; c < graph->comparisons.size(); ++c) {
    std::vector<const GroundExpression*> stack{&graph->comparisons[c]->left, &graph->comparisons[c]->right};
    while (!stack.empty()) {
      const GroundExpression* e = stack.back();
      stack.pop_back();
      if (e->kind == GroundExpression::Kind::Variable) graph->comparison_variables[c].push_back(e->variable);
      for (const GroundExpression& o : e->operands) stack.push_back(&o);
    }
  }
  for (ActionId a = 0; a < graph->actions.size(); ++a) {
    for (const auto* list : {&graph->actions[a].start_numeric, &graph->actions[a].end_numeric}) {
      for (std::uint32_t c : *list) {
        for (NumericVarId v : graph->comparison_variables[c]) graph->numeric_watchers[v].push_back(a);
      }
    }
  }
  return graph;
}

}  // namespace alplan
