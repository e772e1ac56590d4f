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

bool GroundTask::is_derived(FactId fact) const { return lifted->predicates[facts.key(fact).head].derived; }

}  // namespace alplan
