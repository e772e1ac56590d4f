// The pieces of the Python module `alplan` (module.cpp puts them together).
// The module is a thin shell over the libraries, like the CLI: arguments in,
// library calls out, results as plain Python objects.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "pddl_parser/ast.h"
#include "pddl_parser/source_location.h"

namespace alplan::python {

namespace py = pybind11;

// A parsed and checked domain or problem, with the warnings it gave.
struct PyDomain {
  std::shared_ptr<const pddl::Domain> ast;
  std::string file;
  std::vector<std::string> warnings;
};
struct PyProblem {
  std::shared_ptr<const pddl::Problem> ast;
  std::string file;
  std::vector<std::string> warnings;
};

// alplan.PddlError(ValueError) with .file, .line, .column (the first error)
// and .diagnostics (every one, as text). Raised from C++ by this.
[[noreturn]] void raise_pddl_error(const std::vector<pddl::Diagnostic>& diagnostics);

// Reads and checks; raises PddlError (or OSError for a missing file).
PyDomain load_domain(const std::string& text, const std::string& file);
PyProblem load_problem(const std::string& text, const std::string& file, const PyDomain& domain);
std::string read_text_file(const std::string& path);

void add_errors(py::module_& m);
void add_pddl(py::module_& m);
void add_planning(py::module_& m);
void add_monitor(py::module_& m);

// A Domain/Problem object, or a file path to read and check.
PyDomain domain_of(const py::object& d);
PyProblem problem_of(const py::object& p, const PyDomain& domain);

}  // namespace alplan::python
