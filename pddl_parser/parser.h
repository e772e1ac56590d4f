// Entry points of the PDDL parser: text -> immutable AST + diagnostics.
//
// Syntax errors are reported per section: after an error the parser skips to
// the end of the enclosing `(:section ...)` and goes on, so one run reports
// every broken section of a file. Semantic checks (checker.h) run on top.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "pddl_parser/ast.h"
#include "pddl_parser/parser_options.h"
#include "pddl_parser/source_location.h"

namespace alplan::pddl {

template <typename Node>
struct ParseResult {
  std::shared_ptr<const Node> ast;  // null only when nothing could be read
  std::vector<Diagnostic> diagnostics;
  bool ok() const { return ast != nullptr && !has_errors(diagnostics); }
};

using DomainParseResult = ParseResult<Domain>;
using ProblemParseResult = ParseResult<Problem>;

DomainParseResult parse_domain(std::string_view text, const std::string& file_name,
                               const ParserOptions& options = {});
ProblemParseResult parse_problem(std::string_view text, const std::string& file_name,
                                 const ParserOptions& options = {});

enum class FileKind { Domain, Problem, Unknown };

// Reads `(define (domain|problem ...` without parsing the rest.
FileKind detect_file_kind(std::string_view text);

// Reads a whole file; returns false and a diagnostic when it cannot.
bool read_file(const std::string& path, std::string& contents, std::vector<Diagnostic>& diagnostics);

}  // namespace alplan::pddl
