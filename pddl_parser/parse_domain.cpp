// (define (domain ...) sections...): one function per section; a syntax
// error inside a section is reported and the parser resumes after it.
#include "pddl_parser/parser_core.h"

namespace alplan::pddl::detail {
namespace {

std::vector<TypeDeclaration> parse_types(ParserCore& core) {
  std::vector<TypeDeclaration> types;
  for (TypedName& t : parse_typed_list(core, false, "in :types")) {
    types.push_back({std::move(t.name), std::move(t.types), t.location});
  }
  return types;
}

std::vector<PredicateDeclaration> parse_predicates(ParserCore& core) {
  std::vector<PredicateDeclaration> predicates;
  while (!core.at(TokenKind::RightParen)) {
    const SourceLocation where = core.expect_left("to open a predicate declaration");
    PredicateDeclaration p;
    p.location = where;
    p.name = core.expect_symbol("a predicate name");
    p.parameters = parse_typed_list(core, true, "in the parameters of " + p.name);
    core.expect_right("to close the declaration of " + p.name);
    predicates.push_back(std::move(p));
  }
  return predicates;
}

// (:functions (f ?x - t) (g) - number (h) - obj): like a typed list whose
// items are function skeletons; the type defaults to number.
std::vector<FunctionDeclaration> parse_functions(ParserCore& core) {
  std::vector<FunctionDeclaration> functions;
  std::size_t untyped_from = 0;
  while (!core.at(TokenKind::RightParen)) {
    if (core.at_symbol("-")) {
      const SourceLocation dash = core.take().location;
      if (untyped_from == functions.size()) core.fail(dash, "'-' must follow a function declaration");
      const std::string type = core.expect_symbol("'number' or a type name after '-'");
      for (std::size_t i = untyped_from; i < functions.size(); ++i) functions[i].value_type = type;
      untyped_from = functions.size();
      continue;
    }
    const SourceLocation where = core.expect_left("to open a function declaration");
    FunctionDeclaration f;
    f.location = where;
    f.name = core.expect_symbol("a function name");
    f.parameters = parse_typed_list(core, true, "in the parameters of " + f.name);
    core.expect_right("to close the declaration of " + f.name);
    functions.push_back(std::move(f));
  }
  return functions;
}

std::vector<TypedName> parse_parameters(ParserCore& core, const std::string& action) {
  core.expect_left("to open the parameters of " + action);
  std::vector<TypedName> params = parse_typed_list(core, true, "in the parameters of " + action);
  core.expect_right("to close the parameters of " + action);
  return params;
}

// After ':action NAME', the keyword sections follow in any order.
Action parse_action(ParserCore& core, SourceLocation where) {
  Action a;
  a.location = where;
  a.name = core.expect_symbol("an action name after :action");
  while (!core.at(TokenKind::RightParen)) {
    if (core.at_keyword(":parameters")) {
      core.take();
      a.parameters = parse_parameters(core, a.name);
    } else if (core.at_keyword(":precondition")) {
      core.take();
      a.precondition = parse_condition(core);
    } else if (core.at_keyword(":effect")) {
      core.take();
      a.effect = parse_effect(core);
    } else {
      core.fail_expected(":parameters, :precondition or :effect in action " + a.name);
    }
  }
  return a;
}

DurativeAction parse_durative_action(ParserCore& core, SourceLocation where) {
  DurativeAction a;
  a.location = where;
  a.name = core.expect_symbol("an action name after :durative-action");
  while (!core.at(TokenKind::RightParen)) {
    if (core.at_keyword(":parameters")) {
      core.take();
      a.parameters = parse_parameters(core, a.name);
    } else if (core.at_keyword(":duration")) {
      core.take();
      a.duration = parse_duration_constraint(core);
    } else if (core.at_keyword(":condition")) {
      core.take();
      a.condition = parse_condition(core);
    } else if (core.at_keyword(":effect")) {
      core.take();
      a.effect = parse_effect(core);
    } else {
      core.fail_expected(":parameters, :duration, :condition or :effect in durative action " + a.name);
    }
  }
  return a;
}

DerivedPredicate parse_derived(ParserCore& core, SourceLocation where) {
  DerivedPredicate d;
  d.location = where;
  core.expect_left("to open the head of the derived predicate");
  d.name = core.expect_symbol("the name of the derived predicate");
  d.parameters = parse_typed_list(core, true, "in the head of derived predicate " + d.name);
  core.expect_right("to close the head of derived predicate " + d.name);
  d.body = parse_condition(core);
  return d;
}

}  // namespace

void parse_domain_section(ParserCore& core, Domain& domain, SourceLocation where) {
  const Token keyword = core.peek();
  if (keyword.kind != TokenKind::Keyword) core.fail_expected("a section keyword such as :predicates");
  core.take();
  const std::string_view k = keyword.text;
  if (k == ":requirements") {
    for (Requirement& r : parse_requirements_body(core)) domain.requirements.push_back(std::move(r));
  } else if (k == ":types") {
    for (TypeDeclaration& t : parse_types(core)) domain.types.push_back(std::move(t));
  } else if (k == ":constants") {
    for (TypedName& c : parse_typed_list(core, false, "in :constants")) domain.constants.push_back(std::move(c));
  } else if (k == ":predicates") {
    for (PredicateDeclaration& p : parse_predicates(core)) domain.predicates.push_back(std::move(p));
  } else if (k == ":functions") {
    for (FunctionDeclaration& f : parse_functions(core)) domain.functions.push_back(std::move(f));
  } else if (k == ":constraints") {
    domain.constraints = parse_condition(core);
  } else if (k == ":action") {
    domain.actions.push_back(parse_action(core, where));
  } else if (k == ":durative-action") {
    domain.durative_actions.push_back(parse_durative_action(core, where));
  } else if (k == ":derived") {
    domain.derived_predicates.push_back(parse_derived(core, where));
  } else if (k == ":process" || k == ":event") {
    // PDDL+ (Fox & Long 2006): named, so that a user is not sent looking
    // for a typo in a section that is spelled right.
    core.fail(keyword.location, std::string(k == ":process" ? "PDDL+ processes (:process)" : "PDDL+ events (:event)") +
                                    " are not supported: alplan plans PDDL 2.1 durative actions, with continuous "
                                    "effects (#t) inside them, not PDDL+");
  } else {
    core.fail(keyword.location, "unknown domain section " + std::string(k) +
                                    " (expected :requirements, :types, :constants, :predicates, :functions, "
                                    ":constraints, :action, :durative-action or :derived)");
  }
  core.expect_right("to close the " + std::string(k) + " section");
}

}  // namespace alplan::pddl::detail
