// The error diagnostics of a parse or check, one a line, for a test's
// failure message.
#pragma once

#include <string>
#include <vector>

#include "pddl_parser/source_location.h"

namespace alplan::test {

inline std::string errors_of(const std::vector<pddl::Diagnostic>& diagnostics) {
  std::string all;
  for (const pddl::Diagnostic& d : diagnostics) {
    if (d.severity == pddl::Severity::Error) all += d.to_string() + "\n";
  }
  return all;
}

}  // namespace alplan::test
