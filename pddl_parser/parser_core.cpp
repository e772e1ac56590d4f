#include "pddl_parser/parser_core.h"

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <istream>
#include <fstream>
#include <string>

namespace alplan::pddl::detail {

ParserCore::ParserCore(std::string_view text, DiagnosticSink& sink, const ParserOptions& options)
    : lexer_(text), sink_(sink), options_(options) {
  advance();
}

Token ParserCore::fetch() {
  Token token = lexer_.next();
  if (token.glued) {
    warn(token.location, "'-' is written against the name after it; read as a separate '-', as VAL reads it");
  }
  return token;
}

void ParserCore::advance() {
  if (second_) {
    current_ = *second_;
    second_.reset();
    return;
  }
  current_ = fetch();
}

const Token& ParserCore::peek_second() {
  if (!second_) second_ = fetch();
  return *second_;
}

Token ParserCore::take() {
  Token token = current_;
  if (token.kind == TokenKind::Invalid) {
    fail(token.location, "unexpected characters '" + std::string(token.text) +
                             "': PDDL names start with a letter and use letters, digits, '-' and '_'");
  }
  advance();
  return token;
}

std::string ParserCore::describe_current() const {
  switch (current_.kind) {
    case TokenKind::End: return "the end of the file";
    case TokenKind::LeftParen: return "'('";
    case TokenKind::RightParen: return "')'";
    case TokenKind::Number: return "the number " + std::string(current_.text);
    case TokenKind::Variable: return "the variable " + std::string(current_.text);
    case TokenKind::Keyword: return "the keyword " + std::string(current_.text);
    case TokenKind::Symbol: return "'" + std::string(current_.text) + "'";
    case TokenKind::Invalid: return "the invalid text '" + std::string(current_.text) + "'";
  }
  return "?";
}

void ParserCore::fail_expected(std::string_view expected) {
  fail(current_.location, "expected " + std::string(expected) + ", found " + describe_current());
}

void ParserCore::fail(SourceLocation where, std::string message) {
  sink_.error(where, std::move(message));
  throw SyntaxError{};
}

SourceLocation ParserCore::expect_left(std::string_view context) {
  if (!at(TokenKind::LeftParen)) fail_expected("'(' " + std::string(context));
  const SourceLocation where = current_.location;
  advance();
  return where;
}

void ParserCore::expect_right(std::string_view context) {
  if (!at(TokenKind::RightParen)) fail_expected("')' " + std::string(context));
  advance();
}

std::string ParserCore::expect_symbol(std::string_view what) {
  if (!at(TokenKind::Symbol)) fail_expected(what);
  return std::string(take().text);
}

std::string ParserCore::expect_variable(std::string_view what) {
  if (!at(TokenKind::Variable)) fail_expected(what);
  return std::string(take().text);
}

double ParserCore::expect_number(std::string_view what) {
  if (!at(TokenKind::Number)) fail_expected(what);
  return take().number;
}

void ParserCore::expect_exact_symbol(std::string_view text, std::string_view context) {
  if (!at_symbol(text)) fail_expected("'" + std::string(text) + "' " + std::string(context));
  advance();
}

void ParserCore::skip_past_list(int open_depth) {
  while (!at(TokenKind::End)) {
    const bool closes = at(TokenKind::RightParen) && current_.depth == open_depth + 1;
    advance();
    if (closes) return;
  }
}

// Reads `in` to its end. Into the string ourselves: `buffer << in.rdbuf()`
// catches a bad_alloc raised while it copies and only sets failbit, so under
// a memory limit it handed the parser a silently truncated file. Growing the
// string here lets the allocation failure reach the caller.
bool read_stream(std::istream& in, std::string& text) {
  std::array<char, 1 << 16> chunk{};
  while (in.read(chunk.data(), chunk.size()) || in.gcount() > 0) {
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
  }
  return !in.bad();
}

ParserCore::Nesting::Nesting(ParserCore& core) : core_(core) {
  if (++core_.nesting_ > core_.options_.max_nesting) {
    --core_.nesting_;
    core_.fail(core_.current_.location, "expressions nested deeper than " +
                                            std::to_string(core_.options_.max_nesting) + " levels");
  }
}

}  // namespace alplan::pddl::detail

namespace alplan::pddl {

namespace {

// The system's reason for the last failed call, as strerror words it ("No
// such file or directory"), or a plain fallback when it left none.
std::string system_reason(int error) {
  return error != 0 ? std::string(std::strerror(error)) : std::string("the system gave no reason");
}

}  // namespace

bool read_file(const std::string& path, std::string& contents, std::vector<Diagnostic>& diagnostics) {
  std::string text;
  // A directory opens as a stream on Linux and fails only when read, with
  // a reason nobody would guess from "cannot read": say what it is.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    diagnostics.push_back({Severity::Error, path, 0, 0, "cannot open the file: it is a directory"});
    return false;
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    diagnostics.push_back({Severity::Error, path, 0, 0, "cannot open the file: " + system_reason(errno)});
    return false;
  }
  errno = 0;
  if (!detail::read_stream(in, text)) {
    diagnostics.push_back({Severity::Error, path, 0, 0, "cannot read the file: " + system_reason(errno)});
    return false;
  }
  contents = std::move(text);
  return true;
}

}  // namespace alplan::pddl
