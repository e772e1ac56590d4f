#include <fstream>
#include <sstream>

#include <pybind11/stl.h>

#include "pddl_parser/checker.h"
#include "pddl_parser/parser.h"
#include "pddl_parser/writer.h"
#include "python/bindings.h"

namespace alplan::python {
namespace {

std::vector<std::string> warnings_of(const std::vector<pddl::Diagnostic>& diagnostics) {
  std::vector<std::string> out;
  for (const pddl::Diagnostic& d : diagnostics) {
    if (d.severity == pddl::Severity::Warning) out.push_back(d.to_string());
  }
  return out;
}

template <typename Named>
std::vector<std::string> names(const std::vector<Named>& items) {
  std::vector<std::string> out;
  for (const Named& i : items) out.push_back(i.name);
  return out;
}

}  // namespace

std::string read_text_file(const std::string& path) {
  std::string text;
  std::vector<pddl::Diagnostic> io;
  if (!pddl::read_file(path, text, io)) {
    const std::string message = io.empty() ? "cannot read " + path : io.front().to_string();
    PyErr_SetString(PyExc_OSError, message.c_str());
    throw py::error_already_set();
  }
  return text;
}

PyDomain load_domain(const std::string& text, const std::string& file) {
  pddl::DomainParseResult parsed = pddl::parse_domain(text, file);
  std::vector<pddl::Diagnostic> all = parsed.diagnostics;
  if (parsed.ok()) {
    const std::vector<pddl::Diagnostic> checked = pddl::check_domain(*parsed.ast, file);
    all.insert(all.end(), checked.begin(), checked.end());
  }
  if (!parsed.ast || pddl::has_errors(all)) raise_pddl_error(all);
  return {parsed.ast, file, warnings_of(all)};
}

PyProblem load_problem(const std::string& text, const std::string& file, const PyDomain& domain) {
  pddl::ProblemParseResult parsed = pddl::parse_problem(text, file);
  std::vector<pddl::Diagnostic> all = parsed.diagnostics;
  if (parsed.ok()) {
    const std::vector<pddl::Diagnostic> checked = pddl::check_problem(*domain.ast, *parsed.ast, file);
    all.insert(all.end(), checked.begin(), checked.end());
  }
  if (!parsed.ast || pddl::has_errors(all)) raise_pddl_error(all);
  return {parsed.ast, file, warnings_of(all)};
}

void add_pddl(py::module_& m) {
  py::class_<PyDomain>(m, "Domain", "A parsed and checked PDDL domain (immutable).")
      .def_property_readonly("name", [](const PyDomain& d) { return d.ast->name; })
      .def_property_readonly("file", [](const PyDomain& d) { return d.file; })
      .def_property_readonly("requirements", [](const PyDomain& d) { return names(d.ast->requirements); })
      .def_property_readonly("types", [](const PyDomain& d) { return names(d.ast->types); })
      .def_property_readonly("predicates", [](const PyDomain& d) { return names(d.ast->predicates); })
      .def_property_readonly("functions", [](const PyDomain& d) { return names(d.ast->functions); })
      .def_property_readonly("actions",
                             [](const PyDomain& d) {
                               std::vector<std::string> all = names(d.ast->actions);
                               for (const std::string& n : names(d.ast->durative_actions)) all.push_back(n);
                               return all;
                             })
      .def_property_readonly("warnings", [](const PyDomain& d) { return d.warnings; })
      .def("to_pddl", [](const PyDomain& d) { return pddl::write_domain(*d.ast); }, "The domain as canonical PDDL")
      .def("__repr__", [](const PyDomain& d) { return "<alplan.Domain " + d.ast->name + ">"; });

  py::class_<PyProblem>(m, "Problem", "A parsed PDDL problem, checked against its domain (immutable).")
      .def_property_readonly("name", [](const PyProblem& p) { return p.ast->name; })
      .def_property_readonly("file", [](const PyProblem& p) { return p.file; })
      .def_property_readonly("domain_name", [](const PyProblem& p) { return p.ast->domain_name; })
      .def_property_readonly("objects", [](const PyProblem& p) { return names(p.ast->objects); })
      .def_property_readonly("init", [](const PyProblem& p) {
        std::vector<std::string> atoms;
        for (const pddl::Atom& a : p.ast->init) atoms.push_back(pddl::write_atom(a));
        return atoms;
      })
      .def_property_readonly("goal", [](const PyProblem& p) {
        return p.ast->goal ? pddl::write_condition(*p.ast->goal) : std::string("(and)");
      })
      .def_property_readonly("timed_literals", [](const PyProblem& p) { return p.ast->timed_literals.size(); })
      .def_property_readonly("warnings", [](const PyProblem& p) { return p.warnings; })
      .def("to_pddl", [](const PyProblem& p) { return pddl::write_problem(*p.ast); }, "The problem as canonical PDDL")
      .def("__repr__", [](const PyProblem& p) { return "<alplan.Problem " + p.ast->name + ">"; });

  m.def("parse_domain", [](const std::string& path) { return load_domain(read_text_file(path), path); },
        py::arg("path"), "Reads and checks a domain file; raises PddlError naming the place, OSError if unreadable");
  m.def("parse_problem",
        [](const std::string& path, const PyDomain& domain) {
          return load_problem(read_text_file(path), path, domain);
        },
        py::arg("path"), py::arg("domain"), "Reads a problem file and checks it against the domain");
  m.def("parse_domain_string", &load_domain, py::arg("text"), py::arg("file") = "<string>",
        "Parses and checks a domain given as text; `file` names it in errors");
  m.def("parse_problem_string",
        [](const std::string& text, const PyDomain& domain, const std::string& file) {
          return load_problem(text, file, domain);
        },
        py::arg("text"), py::arg("domain"), py::arg("file") = "<string>",
        "Parses a problem given as text and checks it against the domain");
}

}  // namespace alplan::python
