#include "planner/relevance.h"

#include <algorithm>

#include "planner/linear_metric.h"

namespace alplan {
namespace {

// What the analysis has marked and what is still to follow.
class RelevanceMarks {
 public:
  explicit RelevanceMarks(const GroundTask& task)
      : needed_true_(task.facts.size()), needed_false_(task.facts.size()), variable_(task.numeric.size()),
        action_(task.actions.size()) {}

  void fact(FactId f, bool value) {
    std::vector<bool>& marks = value ? needed_true_ : needed_false_;
    if (marks[f]) return;
    marks[f] = true;
    facts_.push_back({f, value});
  }
  void variable(NumericVarId v) {
    if (variable_[v]) return;
    variable_[v] = true;
    variables_.push_back(v);
  }
  void action(ActionId a) {
    if (action_[a]) return;
    action_[a] = true;
    actions_.push_back(a);
  }

  void expression(const GroundExpression& e) {
    if (e.kind == GroundExpression::Kind::Variable) variable(e.variable);
    for (const GroundExpression& o : e.operands) expression(o);
  }
  void formula(const GroundFormula& f) {
    if (f.kind == GroundFormula::Kind::Literal) {
      fact(f.fact, true);
      fact(f.fact, false);
    }
    if (f.kind == GroundFormula::Kind::Comparison) comparison(f.comparison);
    for (const GroundFormula& c : f.children) formula(c);
  }
  void comparison(const GroundComparison& c) {
    expression(c.left);
    expression(c.right);
  }
  void condition(const ConditionSet& c) {
    for (FactId f : c.positive) fact(f, true);
    for (FactId f : c.negative) fact(f, false);
    for (const GroundComparison& n : c.numeric) comparison(n);
    for (const GroundFormula& f : c.complex) formula(f);
  }
  // Either way: a conditional effect may be wanted (its condition made
  // true) or unwanted (made false before the action).
  void either_way(const ConditionSet& c) {
    for (const std::vector<FactId>* facts : {&c.positive, &c.negative}) {
      for (FactId f : *facts) {
        fact(f, true);
        fact(f, false);
      }
    }
    for (const GroundComparison& n : c.numeric) comparison(n);
    for (const GroundFormula& f : c.complex) formula(f);
  }

  std::vector<std::pair<FactId, bool>> facts_;
  std::vector<NumericVarId> variables_;
  std::vector<ActionId> actions_;
  std::vector<bool> needed_true_, needed_false_, variable_, action_;
};

// Who changes what: the actions adding or deleting each fact (conditional
// effects included) and assigning each numeric variable.
struct Changers {
  std::vector<std::vector<ActionId>> adders, deleters, assigners;
  std::vector<std::vector<const GroundAxiom*>> axioms;  // by head

  explicit Changers(const GroundTask& task)
      : adders(task.facts.size()), deleters(task.facts.size()), assigners(task.numeric.size()),
        axioms(task.facts.size()) {
    for (ActionId a = 0; a < task.actions.size(); ++a) {
      for (const HappeningEffects* e : {&task.actions[a].start, &task.actions[a].end}) add(a, *e);
      for (const ContinuousEffect& c : task.actions[a].continuous) push(assigners[c.variable], a);
    }
    for (const GroundAxiom& x : task.axioms) axioms[x.head].push_back(&x);
  }

 private:
  void add(ActionId a, const HappeningEffects& e) {
    note(a, e.add, e.del, e.numeric);
    for (const ConditionalEffect& c : e.conditional) note(a, c.add, c.del, c.numeric);
  }
  void note(ActionId a, const std::vector<FactId>& add, const std::vector<FactId>& del,
            const std::vector<NumericAssignment>& numeric) {
    for (FactId f : add) push(adders[f], a);
    for (FactId f : del) push(deleters[f], a);
    for (const NumericAssignment& n : numeric) push(assigners[n.variable], a);
  }
  static void push(std::vector<ActionId>& list, ActionId a) {
    if (list.empty() || list.back() != a) list.push_back(a);
  }
};

// A metric that only grows as a plan grows (linear_metric.h: minimised,
// non-negative weights on fluents that actions only increase by
// non-negative constants) never wants an action for its effect on it;
// any other metric makes its variables relevant.
void mark_metric(const GroundTask& task, RelevanceMarks& marks) {
  if (!task.metric || linear_metric(task)) return;
  marks.expression(task.metric->expression);
}

void mark_action(const GroundAction& a, RelevanceMarks& marks) {
  for (const ConditionSet* c : {&a.at_start, &a.over_all, &a.at_end}) marks.condition(*c);
  for (const GroundPreference& p : a.preferences) marks.condition(p.condition);
  for (const GroundDurationConstraint& d : a.duration) marks.expression(d.value);
  for (const ContinuousEffect& c : a.continuous) marks.expression(c.rate);
  for (const HappeningEffects* e : {&a.start, &a.end}) {
    for (const NumericAssignment& n : e->numeric) marks.expression(n.value);
    for (const ConditionalEffect& c : e->conditional) {
      marks.either_way(c.condition);
      for (const NumericAssignment& n : c.numeric) marks.expression(n.value);
    }
  }
}

// PDDL 3: a trajectory constraint, hard or soft, may need each fact it
// names true at one time and false at another (an `always (or (not lit)
// (not open))` is kept by an action that deletes `lit`), so its facts are
// relevant both ways; a goal preference is a goal one may give up, relevant
// as a goal is.
void mark_trajectory(const GroundTask& task, RelevanceMarks& marks) {
  for (const GroundConstraint& c : task.pddl3.constraints) {
    marks.either_way(c.requirement);
    marks.either_way(c.trigger);
  }
  for (const GroundPreference& p : task.pddl3.goal_preferences) marks.condition(p.condition);
}

}  // namespace

std::vector<bool> relevant_actions(const GroundTask& task, const std::vector<ActionId>& keep) {
  const Changers changers(task);
  RelevanceMarks marks(task);
  marks.condition(task.goal);
  mark_metric(task, marks);
  mark_trajectory(task, marks);
  for (ActionId a : keep) marks.action(a);
  std::size_t next_fact = 0, next_variable = 0, next_action = 0;
  while (next_fact < marks.facts_.size() || next_variable < marks.variables_.size() ||
         next_action < marks.actions_.size()) {
    while (next_action < marks.actions_.size()) mark_action(task.actions[marks.actions_[next_action++]], marks);
    while (next_variable < marks.variables_.size()) {
      for (ActionId a : changers.assigners[marks.variables_[next_variable]]) marks.action(a);
      ++next_variable;
    }
    while (next_fact < marks.facts_.size()) {
      const auto [f, value] = marks.facts_[next_fact++];
      for (ActionId a : value ? changers.adders[f] : changers.deleters[f]) marks.action(a);
      for (const GroundAxiom* x : changers.axioms[f]) {
        for (FactId b : x->body.positive) marks.fact(b, true), marks.fact(b, false);
        for (FactId b : x->body.negative) marks.fact(b, true), marks.fact(b, false);
        for (const GroundComparison& n : x->body.numeric) marks.comparison(n);
        for (const GroundFormula& g : x->body.complex) marks.formula(g);
      }
    }
  }
  return marks.action_;
}

RelevantView relevant_view(const std::shared_ptr<const GroundTask>& task, const std::vector<ActionId>& keep) {
  const std::vector<bool> relevant = relevant_actions(*task, keep);
  RelevantView view;
  view.new_id.assign(task->actions.size(), kNoId);
  std::vector<GroundAction> kept;
  for (ActionId a = 0; a < task->actions.size(); ++a) {
    if (!relevant[a]) continue;
    view.new_id[a] = static_cast<ActionId>(kept.size());
    kept.push_back(task->actions[a]);
  }
  view.pruned = task->actions.size() - kept.size();
  if (view.pruned == 0) {
    view.task = task;
    return view;
  }
  auto pruned = std::make_shared<GroundTask>(*task);
  pruned->actions = SharedVector<GroundAction>();
  pruned->actions.mutate() = std::move(kept);
  view.task = std::move(pruned);
  return view;
}

RelevantView relevant_view_like(const std::shared_ptr<const GroundTask>& task, const RelevantView& like) {
  RelevantView view = like;
  if (like.pruned == 0) {
    view.task = task;
    return view;
  }
  auto derived = std::make_shared<GroundTask>(*task);
  derived->actions = like.task->actions;
  view.task = std::move(derived);
  return view;
}

}  // namespace alplan
