#include "pddl_parser/lexer.h"

#include <array>
#include <charconv>

namespace alplan::pddl {
namespace {

// Byte classes, built once at compile time so the hot loop is a table lookup.
enum : unsigned char {
  kSpace = 1,
  kDelimiter = 2,  // ends a word: space, parens, ';'
  kNameStart = 4,
  kNameChar = 8,
  kDigit = 16,
};

constexpr std::array<unsigned char, 256> make_classes() {
  std::array<unsigned char, 256> c{};
  for (unsigned char s : {' ', '\t', '\n', '\r', '\f', '\v'}) c[s] = kSpace | kDelimiter;
  c['('] = kDelimiter;
  c[')'] = kDelimiter;
  c[';'] = kDelimiter;
  for (int ch = 'a'; ch <= 'z'; ++ch) c[ch] = kNameStart | kNameChar;
  for (int ch = 'A'; ch <= 'Z'; ++ch) c[ch] = kNameStart | kNameChar;
  for (int ch = '0'; ch <= '9'; ++ch) c[ch] = kNameChar | kDigit;
  c['_'] = kNameStart | kNameChar;
  c['-'] = kNameChar;
  return c;
}
constexpr std::array<unsigned char, 256> kClasses = make_classes();

bool is(char ch, unsigned char cls) { return (kClasses[static_cast<unsigned char>(ch)] & cls) != 0; }

bool all_name_chars(std::string_view s) {
  for (char ch : s) {
    if (!is(ch, kNameChar)) return false;
  }
  return true;
}

// Operators that PDDL writes as bare symbols.
bool is_operator(std::string_view w) {
  return w == "-" || w == "+" || w == "*" || w == "/" || w == "<" || w == ">" || w == "=" ||
         w == "<=" || w == ">=" || w == "#t";
}

}  // namespace

const char* to_string(TokenKind kind) {
  switch (kind) {
    case TokenKind::LeftParen: return "'('";
    case TokenKind::RightParen: return "')'";
    case TokenKind::Symbol: return "a name";
    case TokenKind::Variable: return "a variable";
    case TokenKind::Keyword: return "a keyword";
    case TokenKind::Number: return "a number";
    case TokenKind::End: return "the end of the file";
    case TokenKind::Invalid: return "an invalid character";
  }
  return "?";
}

Lexer::Lexer(std::string_view source) : text_(source) {
  for (char& ch : text_) {
    if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
  }
}

SourceLocation Lexer::here() const {
  return {line_, static_cast<std::uint32_t>(position_ - line_start_ + 1)};
}

void Lexer::skip_space_and_comments() {
  const std::size_t n = text_.size();
  while (position_ < n) {
    const char ch = text_[position_];
    if (ch == '\n') {
      ++position_;
      ++line_;
      line_start_ = position_;
    } else if (is(ch, kSpace)) {
      ++position_;
    } else if (ch == ';') {
      const std::size_t eol = text_.find('\n', position_);
      position_ = eol == std::string::npos ? n : eol;
    } else {
      return;
    }
  }
}

Token Lexer::next() {
  skip_space_and_comments();
  Token token;
  token.location = here();
  token.depth = depth_;
  if (position_ >= text_.size()) {
    token.kind = TokenKind::End;
    return token;
  }
  const char ch = text_[position_];
  if (ch == '(') {
    ++position_;
    ++depth_;
    token.kind = TokenKind::LeftParen;
    token.text = std::string_view(text_).substr(position_ - 1, 1);
    return token;
  }
  if (ch == ')') {
    ++position_;
    --depth_;
    token.kind = TokenKind::RightParen;
    token.text = std::string_view(text_).substr(position_ - 1, 1);
    return token;
  }
  token = word(position_, token.location);
  token.depth = depth_;
  return token;
}

Token Lexer::word(std::size_t start, SourceLocation where) {
  const std::size_t n = text_.size();
  std::size_t end = start;
  while (end < n && !is(text_[end], kDelimiter)) ++end;
  position_ = end;

  Token token;
  token.location = where;
  token.text = std::string_view(text_).substr(start, end - start);
  const std::string_view w = token.text;
  const char first = w.front();

  if (first == '?') {
    token.kind = w.size() > 1 && is(w[1], kNameStart) && all_name_chars(w.substr(1))
                     ? TokenKind::Variable
                     : TokenKind::Invalid;
    return token;
  }
  if (first == ':') {
    token.kind = w.size() > 1 && is(w[1], kNameStart) && all_name_chars(w.substr(1))
                     ? TokenKind::Keyword
                     : TokenKind::Invalid;
    return token;
  }
  if (first == '-' && w.size() > 1 && is(w[1], kNameStart) && all_name_chars(w.substr(1))) {
    // Some IPC 2006 files write "?g -goods": PDDL's grammar is silent on it,
    // and VAL's lexer reads a '-' token and then a name. So do we.
    position_ = start + 1;
    token.text = w.substr(0, 1);
    token.kind = TokenKind::Symbol;
    token.glued = true;
    return token;
  }
  const bool signed_number = (first == '-' || first == '+') && w.size() > 1 &&
                             (is(w[1], kDigit) || w[1] == '.');
  if (is(first, kDigit) || first == '.' || signed_number) {
    const char* begin = w.data() + (first == '+' ? 1 : 0);
    const char* stop = w.data() + w.size();
    auto [ptr, ec] = std::from_chars(begin, stop, token.number, std::chars_format::fixed);
    if (ec == std::errc() && ptr == stop) {
      token.kind = TokenKind::Number;
      return token;
    }
    // Names made of digits and dashes (`1-2`) occur in hand-written problems;
    // PDDL's grammar wants a leading letter, but every planner accepts them.
    token.kind = all_name_chars(w) && first != '-' ? TokenKind::Symbol : TokenKind::Invalid;
    return token;
  }
  if (is(first, kNameStart) && all_name_chars(w)) {
    token.kind = TokenKind::Symbol;
    return token;
  }
  token.kind = is_operator(w) ? TokenKind::Symbol : TokenKind::Invalid;
  return token;
}

}  // namespace alplan::pddl
