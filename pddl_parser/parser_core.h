// Internal to the parser: the token stream with one token of look-ahead (two
// where PDDL needs it), error reporting and recovery. Not installed.
#pragma once

#include <exception>
#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pddl_parser/ast.h"
#include "pddl_parser/lexer.h"
#include "pddl_parser/parser_options.h"

namespace alplan::pddl::detail {

// Thrown after the message has been recorded; caught where a section ends, so
// that the parser can resume at the next section.
struct SyntaxError : std::exception {
  const char* what() const noexcept override { return "PDDL syntax error"; }
};

class ParserCore {
 public:
  ParserCore(std::string_view text, DiagnosticSink& sink, const ParserOptions& options);

  const Token& peek() const { return current_; }
  const Token& peek_second();
  Token take();

  bool at(TokenKind kind) const { return current_.kind == kind; }
  bool at_symbol(std::string_view text) const {
    return current_.kind == TokenKind::Symbol && current_.text == text;
  }
  bool at_keyword(std::string_view text) const {
    return current_.kind == TokenKind::Keyword && current_.text == text;
  }

  SourceLocation expect_left(std::string_view context);
  void expect_right(std::string_view context);
  std::string expect_symbol(std::string_view what);
  std::string expect_variable(std::string_view what);
  double expect_number(std::string_view what);
  void expect_exact_symbol(std::string_view text, std::string_view context);

  // "expected <expected>, found <what the current token is>".
  [[noreturn]] void fail_expected(std::string_view expected);
  [[noreturn]] void fail(SourceLocation where, std::string message);
  void warn(SourceLocation where, std::string message) { sink_.warning(where, std::move(message)); }

  // Recovery: consume tokens up to and including the ')' that closes the
  // list whose '(' stood at parenthesis depth `open_depth`.
  void skip_past_list(int open_depth);

  // Guards recursion so that deeply nested input is an error, not a crash.
  class Nesting {
   public:
    explicit Nesting(ParserCore& core);
    ~Nesting() { --core_.nesting_; }
    Nesting(const Nesting&) = delete;
    Nesting& operator=(const Nesting&) = delete;

   private:
    ParserCore& core_;
  };

  std::string describe_current() const;

 private:
  void advance();
  Token fetch();  // the lexer's next token, warning about a glued '-'

  Lexer lexer_;
  DiagnosticSink& sink_;
  ParserOptions options_;
  Token current_;
  std::optional<Token> second_;
  int nesting_ = 0;
};

// Grammar pieces shared by domains and problems (parse_*.cpp).
std::vector<TypedName> parse_typed_list(ParserCore& core, bool variables, std::string_view context);
TypeNames parse_type_expression(ParserCore& core);
Atom parse_atom_after_name(ParserCore& core, std::string name, SourceLocation where);
std::vector<Term> parse_terms(ParserCore& core, std::string_view context);
NumericExpression parse_numeric_expression(ParserCore& core);
Condition parse_condition(ParserCore& core);
Effect parse_effect(ParserCore& core);
std::vector<DurationConstraint> parse_duration_constraint(ParserCore& core);
std::vector<Requirement> parse_requirements_body(ParserCore& core);
std::optional<Comparison> comparison_from_symbol(std::string_view symbol);

// One `(:keyword ...)` section whose '(' has been read, up to and including
// its closing ')'.
void parse_domain_section(ParserCore& core, Domain& domain, SourceLocation where);
void parse_problem_section(ParserCore& core, Problem& problem, SourceLocation where);

// Reads `in` to its end into `text`; false when the stream went bad. For
// read_file and, on standard input, read_input (parser.h).
bool read_stream(std::istream& in, std::string& text);

}  // namespace alplan::pddl::detail
