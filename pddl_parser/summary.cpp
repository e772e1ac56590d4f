#include "pddl_parser/summary.h"

#include "pddl_parser/writer.h"

namespace alplan::pddl {

std::size_t count_literals(const Condition& condition) {
  switch (condition.kind) {
    case Condition::Kind::Atom:
    case Condition::Kind::Equality:
    case Condition::Kind::Comparison:
      return 1;
    default: {
      std::size_t n = 0;
      for (const Condition& child : condition.children) n += count_literals(child);
      return n;
    }
  }
}

Summary summarize(const Domain& domain, const Problem* problem) {
  Summary s;
  s.domain_name = domain.name;
  for (const Requirement& r : domain.requirements) s.requirements.push_back(r.name);
  s.types = domain.types.size();
  s.constants = domain.constants.size();
  s.predicates = domain.predicates.size();
  s.functions = domain.functions.size();
  s.actions = domain.actions.size();
  s.durative_actions = domain.durative_actions.size();
  s.derived_predicates = domain.derived_predicates.size();
  if (problem == nullptr) return s;
  s.has_problem = true;
  s.problem_name = problem->name;
  s.objects = problem->objects.size();
  s.init_facts = problem->init.size();
  s.numeric_facts = problem->numeric_init.size();
  s.timed_literals = problem->timed_literals.size();
  s.goal_size = problem->goal ? count_literals(*problem->goal) : 0;
  if (problem->metric) {
    s.metric = std::string(problem->metric->minimize ? "minimize " : "maximize ") +
               write_expression(problem->metric->expression);
  }
  return s;
}

}  // namespace alplan::pddl
