// Reads a domain (and optionally a problem) from files, runs the parser and
// the checker, and prints every diagnostic. Shared by the subcommands.
#pragma once

#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

#include "pddl_parser/ast.h"

namespace alplan::cli {

struct TaskFiles {
  std::shared_ptr<const pddl::Domain> domain;
  std::shared_ptr<const pddl::Problem> problem;  // null when no problem was given
};

struct LoadOptions {
  bool show_warnings = true;
};

// The name diagnostics give an input: the path, or "<stdin>" for "-".
std::string input_name(const std::string& path);

// Null on any error; the diagnostics went to `diagnostics`. Either path may
// be "-" (pddl::kStandardInput), not both: standard input is read once.
std::optional<TaskFiles> load_task_files(const std::string& domain_path, const std::string& problem_path,
                                         std::ostream& diagnostics, const LoadOptions& options = {});

}  // namespace alplan::cli
