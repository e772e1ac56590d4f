#include "pddl_parser/lexer.h"

#include <catch2/catch.hpp>

#include <vector>

using alplan::pddl::Lexer;
using alplan::pddl::Token;
using alplan::pddl::TokenKind;

namespace {

std::vector<Token> lex_all(Lexer& lexer) {
  std::vector<Token> tokens;
  for (Token t = lexer.next(); t.kind != TokenKind::End; t = lexer.next()) tokens.push_back(t);
  return tokens;
}

}  // namespace

TEST_CASE("lexer lower-cases symbols, variables and keywords") {
  Lexer lexer("(Define (DOMAIN Zeno) (:Requirements :TYPING) ?X)");
  const std::vector<Token> t = lex_all(lexer);
  REQUIRE(t.size() == 12);
  CHECK(t[1].text == "define");
  CHECK(t[3].text == "domain");
  CHECK(t[4].text == "zeno");
  CHECK(t[7].kind == TokenKind::Keyword);
  CHECK(t[7].text == ":requirements");
  CHECK(t[8].text == ":typing");
  CHECK(t[10].kind == TokenKind::Variable);
  CHECK(t[10].text == "?x");
}

TEST_CASE("lexer skips comments and tracks lines and columns") {
  Lexer lexer("; a comment (with parens)\n  (at ; trailing\n\t?x)");
  const std::vector<Token> t = lex_all(lexer);
  REQUIRE(t.size() == 4);
  CHECK(t[0].kind == TokenKind::LeftParen);
  CHECK(t[0].location.line == 2);
  CHECK(t[0].location.column == 3);
  CHECK(t[1].text == "at");
  CHECK(t[1].location.column == 4);
  CHECK(t[2].location.line == 3);
  CHECK(t[2].location.column == 2);
}

TEST_CASE("lexer reads numbers, including negative and fractional ones") {
  Lexer lexer("12 12.5 -3 .25 0.001 - 1-2 <= #t");
  const std::vector<Token> t = lex_all(lexer);
  REQUIRE(t.size() == 9);
  CHECK(t[0].kind == TokenKind::Number);
  CHECK(t[0].number == 12.0);
  CHECK(t[1].number == 12.5);
  CHECK(t[2].number == -3.0);
  CHECK(t[3].number == 0.25);
  CHECK(t[4].number == Approx(0.001));
  CHECK(t[5].kind == TokenKind::Symbol);  // the dash of typed lists
  CHECK(t[5].text == "-");
  CHECK(t[6].kind == TokenKind::Symbol);  // digit-led names as some problems use
  CHECK(t[7].text == "<=");
  CHECK(t[8].text == "#t");
}

TEST_CASE("lexer records the parenthesis depth before each token") {
  Lexer lexer("(a (b) c)");
  const std::vector<Token> t = lex_all(lexer);
  REQUIRE(t.size() == 7);
  CHECK(t[0].depth == 0);
  CHECK(t[1].depth == 1);
  CHECK(t[3].depth == 2);
  CHECK(t[4].depth == 2);  // the ')' closing (b)
  CHECK(t[6].depth == 1);  // the final ')'
}

TEST_CASE("lexer marks bytes that cannot form a token as invalid") {
  Lexer lexer("(a $b ?1 :: \xff\xfe x)");
  const std::vector<Token> t = lex_all(lexer);
  REQUIRE(t.size() == 8);
  CHECK(t[2].kind == TokenKind::Invalid);
  CHECK(t[3].kind == TokenKind::Invalid);
  CHECK(t[4].kind == TokenKind::Invalid);
  CHECK(t[5].kind == TokenKind::Invalid);
  CHECK(t[6].text == "x");
}

TEST_CASE("lexer handles empty input and a comment without a final newline") {
  Lexer empty("");
  CHECK(empty.next().kind == TokenKind::End);
  Lexer comment(";; nothing else");
  CHECK(comment.next().kind == TokenKind::End);
}
