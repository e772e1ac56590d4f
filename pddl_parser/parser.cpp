#include "pddl_parser/parser.h"

#include <functional>
#include <iostream>

#include "pddl_parser/lexer.h"
#include "pddl_parser/parser_core.h"

namespace alplan::pddl {
namespace {

using detail::ParserCore;
using detail::SyntaxError;

// (define (domain|problem NAME) ...): reads the header, returns the name and
// where the definition began.
std::string parse_define_header(ParserCore& core, std::string_view kind) {
  core.expect_left("to open (define ...)");
  core.expect_exact_symbol("define", "at the start of the definition");
  core.expect_left("to open (" + std::string(kind) + " NAME)");
  if (!core.at_symbol(kind)) {
    if (core.at_symbol("domain") || core.at_symbol("problem")) {
      core.fail_expected("a " + std::string(kind) + " definition");
    }
    core.fail_expected("'" + std::string(kind) + "'");
  }
  core.take();
  std::string name = core.expect_symbol("the " + std::string(kind) + " name");
  core.expect_right("after the " + std::string(kind) + " name");
  return name;
}

// Parses `(:section ...)` entries until the ')' that closes define; a syntax
// error inside one section is reported and parsing resumes after it.
void parse_sections(ParserCore& core, const std::function<void(SourceLocation)>& section) {
  while (!core.at(TokenKind::RightParen) && !core.at(TokenKind::End)) {
    const int depth = core.peek().depth;
    try {
      section(core.expect_left("to open a section"));
    } catch (const SyntaxError&) {
      core.skip_past_list(depth);
    }
  }
  try {
    core.expect_right("to close (define ...)");
    if (!core.at(TokenKind::End)) core.fail_expected("the end of the file after (define ...)");
  } catch (const SyntaxError&) {
  }
}

template <typename Node, typename SectionParser>
ParseResult<Node> parse_definition(std::string_view text, const std::string& file_name,
                                   const ParserOptions& options, std::string_view kind,
                                   SectionParser section_parser) {
  DiagnosticSink sink(file_name);
  auto node = std::make_shared<Node>();
  try {
    ParserCore core(text, sink, options);
    node->location = core.peek().location;
    node->name = parse_define_header(core, kind);
    parse_sections(core, [&](SourceLocation where) { section_parser(core, *node, where); });
  } catch (const SyntaxError&) {
    return {nullptr, sink.take()};
  }
  return {std::move(node), sink.take()};
}

}  // namespace

DomainParseResult parse_domain(std::string_view text, const std::string& file_name,
                               const ParserOptions& options) {
  return parse_definition<Domain>(text, file_name, options, "domain", detail::parse_domain_section);
}

ProblemParseResult parse_problem(std::string_view text, const std::string& file_name,
                                 const ParserOptions& options) {
  ProblemParseResult result =
      parse_definition<Problem>(text, file_name, options, "problem", detail::parse_problem_section);
  if (result.ast && result.ast->domain_name.empty()) {
    result.diagnostics.push_back({Severity::Error, file_name, result.ast->location.line, result.ast->location.column,
                                  "the problem does not name its domain: add (:domain NAME)"});
  }
  return result;
}

FileKind detect_file_kind(std::string_view text) {
  Lexer lexer(text.substr(0, std::min<std::size_t>(text.size(), 1 << 16)));
  for (int i = 0; i < 4; ++i) {
    const Token t = lexer.next();
    if (t.kind == TokenKind::End) break;
    if (i == 3 && t.kind == TokenKind::Symbol) {
      if (t.text == "domain") return FileKind::Domain;
      if (t.text == "problem") return FileKind::Problem;
    }
  }
  return FileKind::Unknown;
}

bool read_input(const std::string& path, std::string& contents, std::vector<Diagnostic>& diagnostics) {
  if (path != kStandardInput) return read_file(path, contents, diagnostics);
  std::string text;
  if (!detail::read_stream(std::cin, text)) {
    diagnostics.push_back({Severity::Error, path, 0, 0, "cannot read standard input"});
    return false;
  }
  contents = std::move(text);
  return true;
}

}  // namespace alplan::pddl
