// Goal descriptions: preconditions, durative conditions, goals, derived
// predicate bodies and PDDL 3 constraints. The parser accepts every form in
// every place; checker.cpp says where a form is not allowed.
#include <unordered_map>

#include "pddl_parser/parser_core.h"

namespace alplan::pddl::detail {
namespace {

using Kind = Condition::Kind;

Condition node(Kind kind, SourceLocation where) {
  Condition c;
  c.kind = kind;
  c.location = where;
  return c;
}

void parse_children_until_close(ParserCore& core, Condition& c, std::string_view name) {
  while (!core.at(TokenKind::RightParen)) c.children.push_back(parse_condition(core));
  core.expect_right("to close (" + std::string(name) + " ...)");
}

void parse_exactly(ParserCore& core, Condition& c, std::size_t n, std::string_view name) {
  for (std::size_t i = 0; i < n; ++i) {
    if (core.at(TokenKind::RightParen)) {
      core.fail_expected("a condition: (" + std::string(name) + " ...) takes " + std::to_string(n));
    }
    c.children.push_back(parse_condition(core));
  }
  core.expect_right("to close (" + std::string(name) + " ...)");
}

Condition parse_quantified(ParserCore& core, Kind kind, SourceLocation where, std::string_view name) {
  Condition c = node(kind, where);
  core.expect_left("to open the variables of " + std::string(name));
  c.variables = parse_typed_list(core, true, "in the variables of " + std::string(name));
  core.expect_right("to close the variables of " + std::string(name));
  parse_exactly(core, c, 1, name);
  return c;
}

// (= a b) compares objects when both sides are plain terms; otherwise it is a
// numeric comparison. A bare name on a numeric side is a 0-ary function.
Condition parse_comparison(ParserCore& core, Comparison comparison, SourceLocation where) {
  auto plain_term = [&] { return core.at(TokenKind::Symbol) || core.at(TokenKind::Variable); };
  if (comparison == Comparison::Equal && plain_term()) {
    const Token& second = core.peek_second();
    const bool second_plain = second.kind == TokenKind::Symbol || second.kind == TokenKind::Variable;
    if (second_plain) {
      Condition c = node(Kind::Equality, where);
      c.atom.name = "=";
      c.atom.location = where;
      c.atom.args = parse_terms(core, "in (= ...)");
      if (c.atom.args.size() != 2) {
        core.fail(where, "(= ...) compares two terms, found " + std::to_string(c.atom.args.size()));
      }
      core.expect_right("to close (= ...)");
      return c;
    }
  }
  Condition c = node(Kind::Comparison, where);
  c.comparison = comparison;
  c.expressions.push_back(parse_numeric_expression(core));
  c.expressions.push_back(parse_numeric_expression(core));
  core.expect_right("after the two operands of a comparison");
  return c;
}

Condition parse_with_numbers(ParserCore& core, Kind kind, SourceLocation where, std::size_t numbers,
                             std::size_t conditions, std::string_view name) {
  Condition c = node(kind, where);
  for (std::size_t i = 0; i < numbers; ++i) {
    c.numbers.push_back(core.expect_number("a number in (" + std::string(name) + " ...)"));
  }
  parse_exactly(core, c, conditions, name);
  return c;
}

// `at` opens a timed condition only as (at start C) / (at end C); otherwise it
// is the common predicate named `at`.
bool opens_timed(ParserCore& core) {
  if (!core.at_symbol("start") && !core.at_symbol("end")) return false;
  return core.peek_second().kind == TokenKind::LeftParen;
}

Condition parse_timed(ParserCore& core, TimeSpecifier time, SourceLocation where) {
  Condition c = node(Kind::Timed, where);
  c.time = time;
  parse_exactly(core, c, 1, to_string(time));
  return c;
}

struct Modal {
  Kind kind;
  std::size_t numbers;
  std::size_t conditions;
};

const std::unordered_map<std::string_view, Modal>& modal_operators() {
  static const std::unordered_map<std::string_view, Modal> table = {
      {"always", {Kind::Always, 0, 1}},
      {"sometime", {Kind::Sometime, 0, 1}},
      {"within", {Kind::Within, 1, 1}},
      {"at-most-once", {Kind::AtMostOnce, 0, 1}},
      {"sometime-after", {Kind::SometimeAfter, 0, 2}},
      {"sometime-before", {Kind::SometimeBefore, 0, 2}},
      {"always-within", {Kind::AlwaysWithin, 1, 2}},
      {"hold-during", {Kind::HoldDuring, 2, 1}},
      {"hold-after", {Kind::HoldAfter, 1, 1}},
  };
  return table;
}

Condition parse_preference(ParserCore& core, SourceLocation where) {
  Condition c = node(Kind::Preference, where);
  if (core.at(TokenKind::Symbol) && core.peek_second().kind != TokenKind::RightParen) {
    c.preference_name = core.expect_symbol("a preference name");
  }
  parse_exactly(core, c, 1, "preference");
  return c;
}

}  // namespace

Condition parse_condition(ParserCore& core) {
  ParserCore::Nesting guard(core);
  const SourceLocation where = core.expect_left("to open a condition");
  if (core.at(TokenKind::RightParen)) {  // () is the empty conjunction
    core.take();
    return node(Kind::And, where);
  }
  if (!core.at(TokenKind::Symbol)) core.fail_expected("a predicate name or a connective after '('");
  const Token head = core.take();
  const std::string_view h = head.text;

  if (h == "and" || h == "or") {
    Condition c = node(h == "and" ? Kind::And : Kind::Or, where);
    parse_children_until_close(core, c, h);
    return c;
  }
  if (h == "not") {
    Condition c = node(Kind::Not, where);
    parse_exactly(core, c, 1, "not");
    return c;
  }
  if (h == "imply") {
    Condition c = node(Kind::Imply, where);
    parse_exactly(core, c, 2, "imply");
    return c;
  }
  if (h == "exists" || h == "forall") {
    return parse_quantified(core, h == "exists" ? Kind::Exists : Kind::Forall, where, h);
  }
  if (auto comparison = comparison_from_symbol(h)) return parse_comparison(core, *comparison, where);
  if (h == "at" && opens_timed(core)) {
    const bool start = core.take().text == "start";
    return parse_timed(core, start ? TimeSpecifier::AtStart : TimeSpecifier::AtEnd, where);
  }
  if (h == "over" && core.at_symbol("all") && core.peek_second().kind == TokenKind::LeftParen) {
    core.take();
    return parse_timed(core, TimeSpecifier::OverAll, where);
  }
  if (h == "preference") return parse_preference(core, where);
  if (auto it = modal_operators().find(h); it != modal_operators().end()) {
    return parse_with_numbers(core, it->second.kind, where, it->second.numbers, it->second.conditions, h);
  }
  if (h == "-" || h == "+" || h == "*" || h == "/" || h == "#t") {
    core.fail(head.location, "expected a condition, found the numeric operator '" + std::string(h) + "'");
  }
  Condition c = node(Kind::Atom, where);
  c.atom = parse_atom_after_name(core, std::string(h), where);
  return c;
}

}  // namespace alplan::pddl::detail
