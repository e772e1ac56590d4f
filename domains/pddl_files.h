// Reads, parses and checks a domain and a problem file; any error becomes an
// exception whose message lists every diagnostic with its file:line:col.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "pddl_parser/ast.h"

namespace alplan::domains {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LoadedFiles {
  std::shared_ptr<const pddl::Domain> domain;
  std::shared_ptr<const pddl::Problem> problem;
};

LoadedFiles load_pddl(const std::string& domain_path, const std::string& problem_path);
// The same for text already in memory (the names go into diagnostics).
LoadedFiles load_pddl_text(const std::string& domain_text, const std::string& domain_name,
                           const std::string& problem_text, const std::string& problem_name);

}  // namespace alplan::domains
