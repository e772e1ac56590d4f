#include "pddl_parser/ast.h"

namespace alplan::pddl {

const char* to_string(Comparison comparison) {
  switch (comparison) {
    case Comparison::Less: return "<";
    case Comparison::LessEqual: return "<=";
    case Comparison::Equal: return "=";
    case Comparison::GreaterEqual: return ">=";
    case Comparison::Greater: return ">";
  }
  return "?";
}

const char* to_string(TimeSpecifier time) {
  switch (time) {
    case TimeSpecifier::AtStart: return "at start";
    case TimeSpecifier::AtEnd: return "at end";
    case TimeSpecifier::OverAll: return "over all";
  }
  return "?";
}

const char* to_string(AssignOperator assign) {
  switch (assign) {
    case AssignOperator::Assign: return "assign";
    case AssignOperator::Increase: return "increase";
    case AssignOperator::Decrease: return "decrease";
    case AssignOperator::ScaleUp: return "scale-up";
    case AssignOperator::ScaleDown: return "scale-down";
  }
  return "?";
}

}  // namespace alplan::pddl
