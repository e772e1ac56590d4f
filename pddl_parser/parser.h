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

// Reads a whole file. Returns false and a diagnostic naming the path and
// the system's reason ("cannot open the file: No such file or directory")
// when it cannot.
bool read_file(const std::string& path, std::string& contents, std::vector<Diagnostic>& diagnostics);

// The path that names standard input on a command line, as most Unix tools
// read it.
inline constexpr const char* kStandardInput = "-";

// read_file, but kStandardInput reads standard input to its end (so it can
// be read once: a second read finds it empty). For command lines; a library
// caller naming a file "-" means the file.
bool read_input(const std::string& path, std::string& contents, std::vector<Diagnostic>& diagnostics);

}  // namespace alplan::pddl
