#include <pybind11/eval.h>
#include <pybind11/stl.h>

#include "python/bindings.h"

namespace alplan::python {

void add_errors(py::module_& m) {
  // A Python class, so that it carries attributes and can be caught as a
  // ValueError; its type lives in the module, not in a C++ static.
  py::exec(R"(
class PddlError(ValueError):
    """A PDDL file (or string) that does not parse or check: where and what.

    file, line, column: the first error's place; diagnostics: every error and
    warning as 'file:line:col: error: message'."""
    def __init__(self, message, file="", line=0, column=0, diagnostics=()):
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.diagnostics = list(diagnostics)
)",
           m.attr("__dict__"));
}

void raise_pddl_error(const std::vector<pddl::Diagnostic>& diagnostics) {
  const pddl::Diagnostic* first = nullptr;
  std::vector<std::string> lines;
  for (const pddl::Diagnostic& d : diagnostics) {
    lines.push_back(d.to_string());
    if (!first && d.severity == pddl::Severity::Error) first = &d;
  }
  const py::object error_type = py::module_::import("alplan").attr("PddlError");
  const std::string message = first ? first->to_string() : std::string("invalid PDDL");
  const py::object error = error_type(message, first ? first->file : "", first ? first->line : 0,
                                      first ? first->column : 0, lines);
  PyErr_SetObject(error_type.ptr(), error.ptr());
  throw py::error_already_set();
}

}  // namespace alplan::python
