#include "pddl_parser/source_location.h"

namespace alplan::pddl {

std::string Diagnostic::to_string() const {
  std::string out = file;
  // Line 0 is no place in the file (it could not be opened, say): a
  // "file:0:0" would send a reader looking for a line that is not there.
  if (line != 0) {
    out += ':';
    out += std::to_string(line);
    out += ':';
    out += std::to_string(column);
  }
  out += severity == Severity::Error ? ": error: " : ": warning: ";
  out += message;
  return out;
}

void DiagnosticSink::error(SourceLocation where, std::string message) {
  ++errors_;
  if (errors_ > kMaxErrors) {
    if (errors_ == kMaxErrors + 1) {
      diagnostics_.push_back({Severity::Error, file_, where.line, where.column,
                              "too many errors; the rest of this file is not reported"});
    }
    return;
  }
  diagnostics_.push_back({Severity::Error, file_, where.line, where.column, std::move(message)});
}

void DiagnosticSink::warning(SourceLocation where, std::string message) {
  if (diagnostics_.size() > 2 * kMaxErrors) return;
  diagnostics_.push_back({Severity::Warning, file_, where.line, where.column, std::move(message)});
}

bool has_errors(const std::vector<Diagnostic>& diagnostics) {
  for (const Diagnostic& d : diagnostics) {
    if (d.severity == Severity::Error) return true;
  }
  return false;
}

}  // namespace alplan::pddl
