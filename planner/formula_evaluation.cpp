#include "planner/formula_evaluation.h"

#include "planner/ground_printer.h"

namespace alplan {

bool compare_values(pddl::Comparison comparison, double left, double right, double slack) {
  const double d = left - right;
  switch (comparison) {
    case pddl::Comparison::Less: return d < slack;
    case pddl::Comparison::LessEqual: return d <= slack;
    case pddl::Comparison::Equal: return slack > 0 ? std::fabs(d) < slack : d == 0.0;
    case pddl::Comparison::GreaterEqual: return d >= -slack;
    case pddl::Comparison::Greater: return d > -slack;
  }
  return false;
}

std::string describe(const GroundTask& task, const ConditionSet& c, const Unsatisfied& where) {
  using P = Unsatisfied::Part;
  switch (where.part) {
    case P::Never: return *c.never;
    case P::Positive: return task.fact_name(c.positive[where.index]);
    case P::Negative: return "(not " + task.fact_name(c.negative[where.index]) + ")";
    case P::Numeric: return write_comparison(task, c.numeric[where.index]);
    case P::Complex: return write_formula(task, c.complex[where.index]);
  }
  return "?";
}

}  // namespace alplan
