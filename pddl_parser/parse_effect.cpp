// Effects (with timed, conditional, universal and numeric parts) and the
// duration constraints of durative actions.
#include "pddl_parser/parser_core.h"

namespace alplan::pddl::detail {
namespace {

using Kind = Effect::Kind;

Effect node(Kind kind, SourceLocation where) {
  Effect e;
  e.kind = kind;
  e.location = where;
  return e;
}

std::optional<AssignOperator> assign_operator(std::string_view symbol) {
  if (symbol == "assign") return AssignOperator::Assign;
  if (symbol == "increase") return AssignOperator::Increase;
  if (symbol == "decrease") return AssignOperator::Decrease;
  if (symbol == "scale-up") return AssignOperator::ScaleUp;
  if (symbol == "scale-down") return AssignOperator::ScaleDown;
  return std::nullopt;
}

Effect parse_numeric_effect(ParserCore& core, AssignOperator op, SourceLocation where) {
  Effect e = node(Kind::Numeric, where);
  e.assign = op;
  const std::string context = std::string("in (") + to_string(op) + " ...)";
  if (core.at(TokenKind::Symbol)) {  // a 0-ary function written bare
    const Token t = core.take();
    e.atom.name = std::string(t.text);
    e.atom.location = t.location;
  } else {
    const SourceLocation open = core.expect_left("to open the function term " + context);
    e.atom = parse_atom_after_name(core, core.expect_symbol("a function name " + context), open);
  }
  e.value = parse_numeric_expression(core);
  core.expect_right("to close (" + std::string(to_string(op)) + " ...)");
  return e;
}

Effect parse_single(ParserCore& core, std::string_view name) {
  if (core.at(TokenKind::RightParen)) core.fail_expected("an effect inside (" + std::string(name) + " ...)");
  return parse_effect(core);
}

}  // namespace

Effect parse_effect(ParserCore& core) {
  ParserCore::Nesting guard(core);
  const SourceLocation where = core.expect_left("to open an effect");
  if (core.at(TokenKind::RightParen)) {  // () is the empty effect
    core.take();
    return node(Kind::And, where);
  }
  if (!core.at(TokenKind::Symbol)) core.fail_expected("a predicate name or an effect keyword after '('");
  const Token head = core.take();
  const std::string_view h = head.text;

  if (h == "and") {
    Effect e = node(Kind::And, where);
    while (!core.at(TokenKind::RightParen)) e.children.push_back(parse_effect(core));
    core.take();
    return e;
  }
  if (h == "not") {
    Effect e = node(Kind::Delete, where);
    const SourceLocation open = core.expect_left("to open the atom that (not ...) deletes");
    e.atom = parse_atom_after_name(core, core.expect_symbol("a predicate name in (not ...)"), open);
    core.expect_right("to close (not ...): an effect deletes one atom");
    return e;
  }
  if (h == "forall") {
    Effect e = node(Kind::Forall, where);
    core.expect_left("to open the variables of forall");
    e.variables = parse_typed_list(core, true, "in the variables of forall");
    core.expect_right("to close the variables of forall");
    e.children.push_back(parse_single(core, "forall"));
    core.expect_right("to close (forall ...)");
    return e;
  }
  if (h == "when") {
    Effect e = node(Kind::When, where);
    if (core.at(TokenKind::RightParen)) core.fail_expected("a condition in (when ...)");
    e.condition = parse_condition(core);
    e.children.push_back(parse_single(core, "when"));
    core.expect_right("to close (when C E)");
    return e;
  }
  if (h == "at" && (core.at_symbol("start") || core.at_symbol("end")) &&
      core.peek_second().kind == TokenKind::LeftParen) {
    Effect e = node(Kind::Timed, where);
    e.time = core.take().text == "start" ? TimeSpecifier::AtStart : TimeSpecifier::AtEnd;
    e.children.push_back(parse_single(core, to_string(e.time)));
    core.expect_right(std::string("to close (") + to_string(e.time) + " ...)");
    return e;
  }
  if (auto op = assign_operator(h)) return parse_numeric_effect(core, *op, where);
  if (comparison_from_symbol(h) || h == "or" || h == "exists" || h == "imply") {
    core.fail(head.location, "expected an effect, found the condition operator '" + std::string(h) + "'");
  }
  Effect e = node(Kind::Add, where);
  e.atom = parse_atom_after_name(core, std::string(h), where);
  return e;
}

std::vector<DurationConstraint> parse_duration_constraint(ParserCore& core) {
  ParserCore::Nesting guard(core);
  const SourceLocation where = core.expect_left("to open a duration constraint");
  if (core.at(TokenKind::RightParen)) {
    core.take();
    return {};
  }
  if (core.at_symbol("and")) {
    core.take();
    std::vector<DurationConstraint> all;
    while (!core.at(TokenKind::RightParen)) {
      for (DurationConstraint& d : parse_duration_constraint(core)) all.push_back(std::move(d));
    }
    core.take();
    return all;
  }
  if (core.at_symbol("at") && (core.peek_second().text == "start" || core.peek_second().text == "end")) {
    core.take();
    const TimeSpecifier time = core.take().text == "start" ? TimeSpecifier::AtStart : TimeSpecifier::AtEnd;
    std::vector<DurationConstraint> inner = parse_duration_constraint(core);
    core.expect_right("to close a timed duration constraint");
    for (DurationConstraint& d : inner) d.time = time;
    return inner;
  }
  if (!core.at(TokenKind::Symbol)) core.fail_expected("'=', '<=' or '>=' in a duration constraint");
  const Token op = core.take();
  const auto comparison = comparison_from_symbol(op.text);
  if (!comparison || *comparison == Comparison::Less || *comparison == Comparison::Greater) {
    core.fail(op.location, "expected '=', '<=' or '>=' in a duration constraint, found '" +
                               std::string(op.text) + "'");
  }
  if (!core.at(TokenKind::Variable) || core.peek().text != "?duration") {
    core.fail_expected("?duration as the left side of a duration constraint");
  }
  core.take();
  DurationConstraint d;
  d.comparison = *comparison;
  d.location = where;
  d.value = parse_numeric_expression(core);
  core.expect_right("to close the duration constraint");
  return {std::move(d)};
}

}  // namespace alplan::pddl::detail
