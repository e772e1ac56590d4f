// Typed lists, terms, atoms and numeric expressions.
#include "pddl_parser/parser_core.h"

namespace alplan::pddl::detail {

TypeNames parse_type_expression(ParserCore& core) {
  if (core.at(TokenKind::Symbol)) return {core.expect_symbol("a type name")};
  if (!core.at(TokenKind::LeftParen)) core.fail_expected("a type name or (either ...)");
  core.take();
  core.expect_exact_symbol("either", "(a composite type is written (either type1 type2 ...))");
  TypeNames names;
  while (core.at(TokenKind::Symbol)) names.push_back(core.expect_symbol("a type name"));
  if (names.empty()) core.fail_expected("a type name inside (either ...)");
  core.expect_right("to close (either ...)");
  return names;
}

std::vector<TypedName> parse_typed_list(ParserCore& core, bool variables, std::string_view context) {
  std::vector<TypedName> result;
  std::size_t untyped_from = 0;  // first entry still waiting for its '- type'
  const TokenKind item = variables ? TokenKind::Variable : TokenKind::Symbol;
  const std::string what = variables ? "a variable" : "a name";
  while (!core.at(TokenKind::RightParen)) {
    if (core.at_symbol("-")) {
      const SourceLocation dash = core.take().location;
      if (untyped_from == result.size()) {
        core.fail(dash, "'-' must follow at least one " + what + " " + std::string(context));
      }
      TypeNames type = parse_type_expression(core);
      for (std::size_t i = untyped_from; i < result.size(); ++i) result[i].types = type;
      untyped_from = result.size();
      continue;
    }
    if (core.at(TokenKind::LeftParen) && untyped_from < result.size() && core.peek_second().text == "either") {
      core.fail(core.peek().location, "missing '-' before the type (either ...) of " + result.back().name +
                                          " " + std::string(context) + ": write " + result.back().name +
                                          " - (either ...)");
    }
    if (!core.at(item)) core.fail_expected(what + " or ')' " + std::string(context));
    const Token token = core.take();
    result.push_back({std::string(token.text), {}, token.location});
  }
  return result;
}

std::vector<Term> parse_terms(ParserCore& core, std::string_view context) {
  std::vector<Term> terms;
  while (!core.at(TokenKind::RightParen)) {
    if (core.at(TokenKind::Variable)) {
      const Token t = core.take();
      terms.push_back({Term::Kind::Variable, std::string(t.text), t.location});
    } else if (core.at(TokenKind::Symbol)) {
      const Token t = core.take();
      terms.push_back({Term::Kind::Name, std::string(t.text), t.location});
    } else {
      core.fail_expected("an object, a variable or ')' " + std::string(context));
    }
  }
  return terms;
}

Atom parse_atom_after_name(ParserCore& core, std::string name, SourceLocation where) {
  Atom atom;
  atom.name = std::move(name);
  atom.location = where;
  atom.args = parse_terms(core, "in (" + atom.name + " ...)");
  core.expect_right("to close (" + atom.name + " ...)");
  return atom;
}

namespace {

NumericExpression number_node(double value, SourceLocation where) {
  NumericExpression e;
  e.kind = NumericExpression::Kind::Number;
  e.value = value;
  e.location = where;
  return e;
}

NumericExpression from_bare_symbol(ParserCore& core) {
  const Token t = core.take();
  NumericExpression e;
  e.location = t.location;
  if (t.text == "#t") {
    e.kind = NumericExpression::Kind::ContinuousTime;
  } else if (t.text == "total-time") {
    e.kind = NumericExpression::Kind::TotalTime;
  } else {
    // A 0-ary function written without parentheses, as some files do.
    e.kind = NumericExpression::Kind::Function;
    e.function.name = std::string(t.text);
    e.function.location = t.location;
  }
  return e;
}

std::optional<NumericExpression::Kind> operator_kind(std::string_view symbol) {
  if (symbol == "+") return NumericExpression::Kind::Add;
  if (symbol == "-") return NumericExpression::Kind::Subtract;
  if (symbol == "*") return NumericExpression::Kind::Multiply;
  if (symbol == "/") return NumericExpression::Kind::Divide;
  return std::nullopt;
}

NumericExpression parse_operation(ParserCore& core, NumericExpression::Kind kind, const Token& op) {
  NumericExpression e;
  e.kind = kind;
  e.location = op.location;
  while (!core.at(TokenKind::RightParen)) e.operands.push_back(parse_numeric_expression(core));
  const std::string name(op.text);
  const std::size_t n = e.operands.size();
  if (kind == NumericExpression::Kind::Subtract && n == 1) {
    e.kind = NumericExpression::Kind::Negate;
  } else if ((kind == NumericExpression::Kind::Subtract || kind == NumericExpression::Kind::Divide) &&
             n != 2) {
    core.fail(op.location, "'" + name + "' takes two operands, found " + std::to_string(n));
  } else if (n < 2 && kind != NumericExpression::Kind::Subtract) {
    core.fail(op.location, "'" + name + "' takes at least two operands, found " + std::to_string(n));
  }
  core.expect_right("to close (" + name + " ...)");
  return e;
}

}  // namespace

NumericExpression parse_numeric_expression(ParserCore& core) {
  ParserCore::Nesting guard(core);
  const Token& t = core.peek();
  switch (t.kind) {
    case TokenKind::Number: {
      const Token n = core.take();
      return number_node(n.number, n.location);
    }
    case TokenKind::Variable: {
      if (t.text != "?duration") {
        core.fail(t.location, "the variable " + std::string(t.text) +
                                  " is not a numeric expression (only ?duration is)");
      }
      NumericExpression e;
      e.kind = NumericExpression::Kind::Duration;
      e.location = core.take().location;
      return e;
    }
    case TokenKind::Symbol:
      if (operator_kind(t.text) || t.text == "=" || comparison_from_symbol(t.text)) break;
      return from_bare_symbol(core);
    case TokenKind::LeftParen: {
      const SourceLocation open = core.take().location;
      if (!core.at(TokenKind::Symbol)) core.fail_expected("an operator or a function name after '('");
      const Token head = core.take();
      if (auto kind = operator_kind(head.text)) return parse_operation(core, *kind, head);
      NumericExpression e;
      e.location = open;
      if (head.text == "total-time") {
        e.kind = NumericExpression::Kind::TotalTime;
        core.expect_right("after (total-time");
      } else if (head.text == "is-violated") {
        e.kind = NumericExpression::Kind::IsViolated;
        e.function.name = core.expect_symbol("a preference name after is-violated");
        e.function.location = head.location;
        core.expect_right("to close (is-violated ...)");
      } else {
        e.kind = NumericExpression::Kind::Function;
        e.function = parse_atom_after_name(core, std::string(head.text), open);
      }
      return e;
    }
    default: break;
  }
  core.fail_expected("a numeric expression");
}

std::optional<Comparison> comparison_from_symbol(std::string_view symbol) {
  if (symbol == "<") return Comparison::Less;
  if (symbol == "<=") return Comparison::LessEqual;
  if (symbol == "=") return Comparison::Equal;
  if (symbol == ">=") return Comparison::GreaterEqual;
  if (symbol == ">") return Comparison::Greater;
  return std::nullopt;
}

std::vector<Requirement> parse_requirements_body(ParserCore& core) {
  std::vector<Requirement> requirements;
  while (!core.at(TokenKind::RightParen)) {
    if (!core.at(TokenKind::Keyword)) core.fail_expected("a requirement such as :strips or ')'");
    const Token t = core.take();
    requirements.push_back({std::string(t.text), t.location});
  }
  return requirements;
}

}  // namespace alplan::pddl::detail
