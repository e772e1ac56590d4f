// Where a piece of PDDL text came from, and the diagnostics that point at it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace alplan::pddl {

// A 1-based line and column in a source file.
//
// Two ASTs are equal when they denote the same PDDL, wherever it was written:
// the round-trip contract parse(write(parse(f))) == parse(f) is stated on
// content. So equality of locations is deliberately always true; compare
// `line` and `column` explicitly when the position itself matters.
struct SourceLocation {
  std::uint32_t line = 0;
  std::uint32_t column = 0;

  friend bool operator==(const SourceLocation&, const SourceLocation&) {
    return true;
  }
};

enum class Severity { Error, Warning };

// One finding about an input file: `file:line:col: error: message`, or
// `file: error: message` when it has no place in the file (line 0).
struct Diagnostic {
  Severity severity = Severity::Error;
  std::string file;
  std::uint32_t line = 0;
  std::uint32_t column = 0;
  std::string message;

  std::string to_string() const;
};

// Collects diagnostics for one file; parsing and checking keep going after an
// error so that a user sees every problem of a file in one run.
class DiagnosticSink {
 public:
  explicit DiagnosticSink(std::string file_name) : file_(std::move(file_name)) {}

  void error(SourceLocation where, std::string message);
  void warning(SourceLocation where, std::string message);

  const std::string& file_name() const { return file_; }
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
  std::vector<Diagnostic> take() { return std::move(diagnostics_); }
  std::size_t error_count() const { return errors_; }

  // A flood of errors from one broken file helps nobody; the sink keeps the
  // first `limit` and counts the rest.
  static constexpr std::size_t kMaxErrors = 200;

 private:
  std::string file_;
  std::vector<Diagnostic> diagnostics_;
  std::size_t errors_ = 0;
};

bool has_errors(const std::vector<Diagnostic>& diagnostics);

}  // namespace alplan::pddl
