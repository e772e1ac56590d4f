// The relaxed planning graph's static part (planner/temporal_rpg.h): each
// action's relaxed preconditions and effects and the watchers that wake it,
// built once per task and shared by the heuristics of tasks that share its
// ground actions (a grounding cache's).
#include "planner/temporal_rpg.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "planner/numeric_effect_analysis.h"
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
  graph->sound_start_watchers.resize(facts);
  graph->end_watchers.resize(facts);
  graph->axiom_watchers.resize(facts);
  graph->numeric_watchers.resize(task.numeric.size());
  graph->actions.resize(task.actions.size());
  // A give-back (an end returning what its start took) is no producer only
  // where every change of its variable is additive: an assignment while the
  // action runs would make the return a real gain.
  std::vector<char> additive_only(task.numeric.size(), 1);
  for (const GroundAction& g : task.actions) {
    for (const HappeningEffects* e : {&g.start, &g.end}) {
      auto note = [&](const std::vector<NumericAssignment>& effects) {
        for (const NumericAssignment& n : effects) {
          if (n.assign != pddl::AssignOperator::Increase && n.assign != pddl::AssignOperator::Decrease) {
            additive_only[n.variable] = 0;
          }
        }
      };
      note(e->numeric);
      for (const ConditionalEffect& c : e->conditional) note(c.numeric);
    }
    for (const ContinuousEffect& c : g.continuous) additive_only[c.variable] = 0;
  }
  // Over-all comparisons, decided after the comparisons' variables are known.
  std::vector<std::pair<ActionId, std::uint32_t>> over_all_comparisons;
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
        (i < unconditional && additive_only[n->variable] && give_back(g, *n) ? r.end_returns : kept).push_back(n);
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
    r.sound_start_numeric = r.start_numeric;
    if (g.durative) {
      // An invariant the start establishes itself is not needed before it.
      for (FactId f : g.over_all.positive) {
        if (std::find(r.start_add.begin(), r.start_add.end(), f) == r.start_add.end()) r.start_pre.push_back(f);
      }
      r.end_pre = g.at_end.positive;
      r.end_pre.insert(r.end_pre.end(), g.over_all.positive.begin(), g.over_all.positive.end());
      const std::uint32_t first = add_comparisons(g.over_all.numeric);
      for (std::uint32_t i = 0; i < g.over_all.numeric.size(); ++i) over_all_comparisons.emplace_back(a, first + i);
      numeric_list(g.at_end, r.end_numeric);
      r.sound_end_numeric = r.end_numeric;
      auto own = [&](FactId f) { return std::find(r.start_add.begin(), r.start_add.end(), f) != r.start_add.end(); };
      for (FactId f : g.over_all.positive) {
        if (!own(f)) r.held_over_all.push_back(f);
      }
      for (FactId f : g.at_end.positive) {
        if (!own(f)) r.held_at_end.push_back(f);
      }
    }
    std::sort(r.start_pre.begin(), r.start_pre.end());
    r.start_pre.erase(std::unique(r.start_pre.begin(), r.start_pre.end()), r.start_pre.end());
    std::sort(r.end_pre.begin(), r.end_pre.end());
    r.end_pre.erase(std::unique(r.end_pre.begin(), r.end_pre.end()), r.end_pre.end());
    r.sound_start_pre = g.at_start.positive;
    std::sort(r.sound_start_pre.begin(), r.sound_start_pre.end());
    r.sound_start_pre.erase(std::unique(r.sound_start_pre.begin(), r.sound_start_pre.end()), r.sound_start_pre.end());
    for (FactId f : r.start_pre) graph->start_watchers[f].push_back(a);
    for (FactId f : r.sound_start_pre) graph->sound_start_watchers[f].push_back(a);
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
  // An over-all comparison is checked as the action starts, unless the
  // start's own effects change what it reads: it must hold after them, not
  // before, so it is checked at the end instead (later is weaker in the
  // relaxation, whose bounds only widen).
  for (const auto& [a, c] : over_all_comparisons) {
    RelaxedAction& r = graph->actions[a];
    bool own = false;
    for (const NumericAssignment* n : r.start_numeric_effects) {
      const std::vector<NumericVarId>& reads = graph->comparison_variables[c];
      own = own || std::find(reads.begin(), reads.end(), n->variable) != reads.end();
    }
    (own ? r.end_numeric : r.start_numeric).push_back(c);
    r.sound_end_numeric.push_back(c);
  }
  graph->amount_readers.resize(task.numeric.size());
  for (ActionId a = 0; a < graph->actions.size(); ++a) {
    const RelaxedAction& r = graph->actions[a];
    for (const bool end : {false, true}) {
      std::vector<NumericVarId> read;
      for (const auto* list : end ? std::vector{&r.end_numeric_effects, &r.end_returns} : std::vector{&r.start_numeric_effects}) {
        for (const NumericAssignment* n : *list) append_variables(n->value, read);
      }
      std::sort(read.begin(), read.end());
      read.erase(std::unique(read.begin(), read.end()), read.end());
      for (NumericVarId v : read) graph->amount_readers[v].emplace_back(a, end);
    }
  }
  for (ActionId a = 0; a < graph->actions.size(); ++a) {
    const RelaxedAction& r = graph->actions[a];
    for (const auto* list : {&r.start_numeric, &r.end_numeric, &r.sound_start_numeric, &r.sound_end_numeric}) {
      for (std::uint32_t c : *list) {
        for (NumericVarId v : graph->comparison_variables[c]) graph->numeric_watchers[v].push_back(a);
      }
    }
  }
  return graph;
}

}  // namespace alplan
