// (define (problem ...) sections...): objects, the initial state with numeric
// values and timed initial literals, the goal, constraints and the metric.
#include "pddl_parser/parser_core.h"

namespace alplan::pddl::detail {
namespace {

// The literal of a timed initial literal: (p args), (not (p args)), or the
// invalid (= (f args) v) which the checker reports.
void parse_timed_literal_body(ParserCore& core, TimedInitialLiteral& til) {
  const SourceLocation open = core.expect_left("to open the literal of a timed initial literal");
  const std::string head = core.expect_symbol("a predicate name, 'not' or '=' in a timed initial literal");
  if (head == "not") {
    til.positive = false;
    const SourceLocation inner = core.expect_left("to open the atom in (not ...)");
    til.atom = parse_atom_after_name(core, core.expect_symbol("a predicate name in (not ...)"), inner);
    core.expect_right("to close (not ...)");
  } else if (head == "=") {
    const SourceLocation inner = core.expect_left("to open the function term in (= ...)");
    til.atom = parse_atom_after_name(core, core.expect_symbol("a function name"), inner);
    til.numeric_value = core.expect_number("a number in (= (f ...) value)");
    core.expect_right("to close (= ...)");
  } else {
    til.atom = parse_atom_after_name(core, head, open);
  }
}

void parse_init_element(ParserCore& core, Problem& problem) {
  const SourceLocation where = core.expect_left("to open an initial fact");
  const Token head = core.peek();
  if (head.kind != TokenKind::Symbol) core.fail_expected("a predicate name, '=' or 'at' in :init");
  core.take();
  if (head.text == "at" && core.at(TokenKind::Number)) {
    TimedInitialLiteral til;
    til.location = where;
    til.time = core.take().number;
    parse_timed_literal_body(core, til);
    core.expect_right("to close (at TIME literal)");
    problem.timed_literals.push_back(std::move(til));
    return;
  }
  if (head.text == "=") {
    NumericFact fact;
    fact.location = where;
    if (core.at(TokenKind::Symbol)) {
      const Token f = core.take();
      fact.function.name = std::string(f.text);
      fact.function.location = f.location;
    } else {
      const SourceLocation inner = core.expect_left("to open the function term of (= ...)");
      fact.function = parse_atom_after_name(core, core.expect_symbol("a function name"), inner);
    }
    fact.value = core.expect_number("a number as the initial value of " + fact.function.name);
    core.expect_right("to close (= ...)");
    problem.numeric_init.push_back(std::move(fact));
    return;
  }
  if (head.text == "not") {
    core.fail(where, "(not ...) in :init: the initial state lists only true facts (closed world)");
  }
  problem.init.push_back(parse_atom_after_name(core, std::string(head.text), where));
}

Metric parse_metric(ParserCore& core, SourceLocation where) {
  Metric metric;
  metric.location = where;
  const std::string direction = core.expect_symbol("'minimize' or 'maximize'");
  if (direction != "minimize" && direction != "maximize") {
    core.fail(where, "expected 'minimize' or 'maximize' after :metric, found '" + direction + "'");
  }
  metric.minimize = direction == "minimize";
  metric.expression = parse_numeric_expression(core);
  return metric;
}

}  // namespace

void parse_problem_section(ParserCore& core, Problem& problem, SourceLocation where) {
  const Token keyword = core.peek();
  if (keyword.kind != TokenKind::Keyword) core.fail_expected("a section keyword such as :init");
  core.take();
  const std::string_view k = keyword.text;
  if (k == ":domain") {
    problem.domain_name_location = core.peek().location;
    problem.domain_name = core.expect_symbol("the domain name");
  } else if (k == ":requirements") {
    for (Requirement& r : parse_requirements_body(core)) problem.requirements.push_back(std::move(r));
  } else if (k == ":objects") {
    for (TypedName& o : parse_typed_list(core, false, "in :objects")) problem.objects.push_back(std::move(o));
  } else if (k == ":init") {
    while (!core.at(TokenKind::RightParen)) parse_init_element(core, problem);
  } else if (k == ":goal") {
    problem.goal = parse_condition(core);
  } else if (k == ":constraints") {
    problem.constraints = parse_condition(core);
  } else if (k == ":metric") {
    problem.metric = parse_metric(core, where);
  } else if (k == ":length") {
    core.warn(keyword.location, ":length is ignored (it only bounds plan length for old planners)");
    core.skip_past_list(keyword.depth - 1);
    return;
  } else {
    core.fail(keyword.location, "unknown problem section " + std::string(k) +
                                    " (expected :domain, :requirements, :objects, :init, :goal, "
                                    ":constraints or :metric)");
  }
  core.expect_right("to close the " + std::string(k) + " section");
}

}  // namespace alplan::pddl::detail
