#include "planner/ground_task.h"

namespace alplan {

std::string GroundTask::fact_name(FactId fact) const {
  const GroundKey& key = facts.key(fact);
  return key_name(key, lifted->predicates[key.head].name, lifted->objects);
}

std::string GroundTask::variable_name(NumericVarId variable) const {
  const GroundKey& key = numeric.key(variable);
  return key_name(key, lifted->functions[key.head].name, lifted->objects);
}

std::string GroundTask::action_name(const GroundAction& action) const {
  std::string s = "(" + lifted->actions[action.schema].name;
  for (ObjectId o : action.args) s += " " + lifted->objects[o];
  return s + ")";
}

bool same_ground_actions(const GroundTask& a, const GroundTask& b) {
  return a.actions.shares_with(b.actions) && a.facts.size() == b.facts.size() &&
         a.numeric.size() == b.numeric.size() && a.axioms.size() == b.axioms.size();
}

void append_variables(const GroundExpression& e, std::vector<NumericVarId>& out) {
  if (e.kind == GroundExpression::Kind::Variable) out.push_back(e.variable);
  for (const GroundExpression& o : e.operands) append_variables(o, out);
}

namespace {

void append_formula_reads(const GroundFormula& f, std::vector<FactId>& facts, std::vector<NumericVarId>& variables) {
  if (f.kind == GroundFormula::Kind::Literal) facts.push_back(f.fact);
  if (f.kind == GroundFormula::Kind::Comparison) {
    append_variables(f.comparison.left, variables);
    append_variables(f.comparison.right, variables);
  }
  for (const GroundFormula& c : f.children) append_formula_reads(c, facts, variables);
}

}  // namespace

void append_reads(const ConditionSet& c, std::vector<FactId>& facts, std::vector<NumericVarId>& variables) {
  facts.insert(facts.end(), c.positive.begin(), c.positive.end());
  facts.insert(facts.end(), c.negative.begin(), c.negative.end());
  facts.insert(facts.end(), c.mentioned.begin(), c.mentioned.end());
  variables.insert(variables.end(), c.mentioned_values.begin(), c.mentioned_values.end());
  for (const GroundComparison& cmp : c.numeric) {
    append_variables(cmp.left, variables);
    append_variables(cmp.right, variables);
  }
  for (const GroundFormula& f : c.complex) append_formula_reads(f, facts, variables);
}

bool GroundTask::is_derived(FactId fact) const { return lifted->predicates[facts.key(fact).head].derived; }

}  // namespace alplan
