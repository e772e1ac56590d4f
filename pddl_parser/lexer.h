// A hand-written PDDL lexer: parentheses, symbols, ?variables, :keywords and
// numbers, with `;` comments skipped. Symbols are case-insensitive, so the
// lexer works on a lower-cased copy of the input (ASCII only: bytes >= 0x80
// are left alone and are rejected outside comments).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "pddl_parser/source_location.h"

namespace alplan::pddl {

enum class TokenKind : unsigned char {
  LeftParen,
  RightParen,
  Symbol,    // name, or an operator such as -, <=, #t
  Variable,  // ?name
  Keyword,   // :name
  Number,
  End,
  Invalid,   // bytes that cannot start or form a token; `text` holds them
};

struct Token {
  TokenKind kind = TokenKind::End;
  std::string_view text;  // lower-cased, points into the lexer's buffer
  double number = 0.0;    // for Number
  int depth = 0;          // parenthesis depth before this token
  SourceLocation location;
  // A '-' written against the name after it ("?g -goods"): split off as
  // VAL's, OPTIC's and Fast Downward's lexers split it; the parser warns.
  bool glued = false;
};

const char* to_string(TokenKind kind);

class Lexer {
 public:
  explicit Lexer(std::string_view source);

  Lexer(const Lexer&) = delete;
  Lexer& operator=(const Lexer&) = delete;

  Token next();

 private:
  void skip_space_and_comments();
  Token word(std::size_t start, SourceLocation where);
  SourceLocation here() const;

  std::string text_;
  std::size_t position_ = 0;
  std::uint32_t line_ = 1;
  std::size_t line_start_ = 0;
  int depth_ = 0;
};

}  // namespace alplan::pddl
