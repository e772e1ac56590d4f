// import alplan: PDDL parsing, grounding, planning and validation.
#include "python/bindings.h"

PYBIND11_MODULE(alplan, m) {
  m.doc() =
      "alplan: a PDDL 2.2 temporal planning toolkit (parser, grounder, POPF/OPTIC-style planner, "
      "VAL-semantics validator).";
  // One version for the package, the module and `alplan --version`: the
  // project's in CMakeLists.txt (setup.py reads it there too).
  m.attr("__version__") = ALPLAN_VERSION;
  alplan::python::add_errors(m);
  alplan::python::add_pddl(m);
  alplan::python::add_planning(m);
#ifndef ALPLAN_PLANNER_ONLY
  alplan::python::add_monitor(m);
#endif
}
