// import alplan: PDDL parsing, grounding, planning and validation.
#include "python/bindings.h"

PYBIND11_MODULE(alplan, m) {
  m.doc() =
      "alplan: a PDDL 2.2 temporal planning toolkit (parser, grounder, POPF/OPTIC-style planner, "
      "VAL-semantics validator).";
  alplan::python::add_errors(m);
  alplan::python::add_pddl(m);
  alplan::python::add_planning(m);
  alplan::python::add_monitor(m);
}
