#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>

#include <pybind11/stl.h>

#include "planner/deadline.h"
#include "planner/grounder.h"
#include "planner/normalize.h"
#include "planner/planner.h"
#include "planner/validator.h"
#include "python/bindings.h"

namespace alplan::python {
namespace {

struct PyStep {
  double time = 0.0;
  std::optional<double> duration;
  std::string action;
  std::vector<std::string> args;
  std::string name() const {
    std::string n = "(" + action;
    for (const std::string& a : args) n += " " + a;
    return n + ")";
  }
};

struct PyFoundPlan {
  std::vector<PyStep> steps;
  double makespan = 0.0;
  std::optional<double> metric, cost;
  double seconds = 0.0;
  std::string engine, text;
};

struct PyPlanResult {
  std::string status, message;
  std::vector<PyFoundPlan> plans;  // each better than the one before
  py::dict statistics;
};

struct PyGroundTask {
  std::shared_ptr<const GroundTask> task;
};

PyFoundPlan found_plan(const FoundPlan& p) {
  PyFoundPlan out;
  for (const PlanStep& s : p.plan.steps) {
    out.steps.push_back({rounded_plan_time(s.time.value_or(0.0)),
                         s.duration ? std::optional<double>(rounded_plan_time(*s.duration)) : std::nullopt, s.action,
                         s.args});
  }
  out.makespan = rounded_plan_time(p.validation.makespan);
  out.metric = p.validation.metric;
  out.cost = p.validation.total_cost;
  out.seconds = p.seconds;
  out.engine = p.engine;
  out.text = p.text;
  return out;
}

// Keyword arguments onto PlannerOptions; an unknown one is a TypeError. The
// search is `search` (ehc, gbfs, wastar, an alias or an expression,
// planner/search_configuration.h) or `alias`; the other keywords are the
// shorthands `alplan plan`'s flags are.
PlannerOptions planner_options(double time_limit, const py::kwargs& options) {
  PlannerOptions o;
  o.time_limit = time_limit;
  SearchShorthands search;
  std::string heuristic = "trpg", order = "steps";
  for (const auto& [key, value] : options) {
    const std::string k = py::str(key);
    if (k == "anytime") search.anytime = value.cast<bool>();
    else if (k == "search" || k == "alias") search.search = value.cast<std::string>();
    else if (k == "heuristic") heuristic = value.cast<std::string>();
    else if (k == "weight") search.knobs.weight = value.cast<double>();
    else if (k == "order") order = value.cast<std::string>();
    else if (k == "epsilon") o.epsilon = value.cast<double>();
    else if (k == "reserve_planning_time") o.reserve_planning_time = value.cast<bool>();
    else if (k == "anytime_min_weight") search.anytime_min_weight = value.cast<double>();
    else if (k == "anytime_expansions") search.anytime_expansions = value.cast<std::uint64_t>();
    else if (k == "ehc_expansions") search.knobs.ehc_expansions = value.cast<std::uint64_t>();
    else throw py::type_error("plan() got an unexpected keyword argument '" + k + "'");
  }
  if (order != "metric" && order != "steps") throw py::value_error("order must be metric or steps, not '" + order + "'");
  if (heuristic != "trpg" && heuristic != "trpg-nohelpful") {
    throw py::value_error("heuristic must be trpg or trpg-nohelpful, not '" + heuristic + "'");
  }
  search.metric_order = order == "metric";
  search.knobs.heuristic.helpful = heuristic == "trpg";
  try {
    o.search = configuration_from(search);
  } catch (const SearchConfigurationError& e) {
    throw py::value_error(e.what());
  }
  return o;
}

PyPlanResult plan(const py::object& domain_arg, const py::object& problem_arg, double time_limit,
                  const py::kwargs& options) {
  const PyDomain domain = domain_of(domain_arg);
  const PyProblem problem = problem_of(problem_arg, domain);
  const PlannerOptions o = planner_options(time_limit, options);
  PlannerResult result;
  double grounding = 0.0;
  std::string grounding_error;
  {
    // The search holds no Python object: other threads run meanwhile.
    py::gil_scoped_release release;
    const auto began = std::chrono::steady_clock::now();
    GroundingOptions g{{domain.file, problem.file, {}}, std::nullopt};
    if (std::isfinite(time_limit)) {
      g.deadline = began + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                               std::chrono::duration<double>(time_limit));
    }
    try {
      const std::shared_ptr<const GroundTask> task = ground(*domain.ast, *problem.ast, g);
      grounding = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
      PlannerOptions remaining = o;
      remaining.time_limit = std::max(0.0, time_limit - grounding);
      result = Planner(task, remaining).plan();
    } catch (const GroundingTimeout&) {
      result.status = PlannerResult::Status::LimitReached;
      result.message = "the time limit was reached while grounding";
    } catch (const GroundingError& e) {
      grounding_error = e.what();
    }
  }
  if (!grounding_error.empty()) throw py::value_error(grounding_error);
  PyPlanResult out;
  out.status = status_name(result.status);
  out.message = result.message;
  for (const FoundPlan& p : result.plans) out.plans.push_back(found_plan(p));
  const SearchStatistics& s = result.statistics;
  out.statistics["expanded"] = s.expanded;
  out.statistics["evaluated"] = s.evaluated;
  out.statistics["generated"] = s.generated;
  out.statistics["duplicates"] = s.duplicates;
  out.statistics["dead_ends"] = s.dead_ends;
  out.statistics["grounding_seconds"] = grounding;
  out.statistics["search_seconds"] = result.times.search;
  return out;
}

}  // namespace

namespace {

struct PyViolation {
  std::string kind, action, condition, other_action, message;
  double time = 0.0;
  std::optional<double> until;
  std::optional<std::uint32_t> plan_line;
};

struct PyValidation {
  bool valid = false;
  double makespan = 0.0, value = 0.0;
  std::optional<double> metric, cost;
  std::optional<PyViolation> violation;
  std::size_t happenings = 0;
};

// A PlanResult (its best plan), plan text, or a plan file's path.
std::pair<std::string, std::string> plan_text_of(const py::object& plan) {
  if (py::isinstance<PyPlanResult>(plan)) {
    const PyPlanResult& r = plan.cast<const PyPlanResult&>();
    if (r.plans.empty()) throw py::value_error("the planning result holds no plan (status " + r.status + ")");
    return {r.plans.back().text, "<plan>"};
  }
  const std::string s = py::str(plan);
  if (s.find('(') != std::string::npos) return {s, "<plan>"};
  return {read_text_file(s), s};
}

PyValidation validate(const py::object& domain_arg, const py::object& problem_arg, const py::object& plan_arg,
                      double epsilon) {
  const PyDomain domain = domain_of(domain_arg);
  const PyProblem problem = problem_of(problem_arg, domain);
  const auto [text, name] = plan_text_of(plan_arg);
  const PlanReadResult read = read_plan(text, name);
  if (!read.ok()) raise_pddl_error(read.diagnostics);
  ValidationResult result;
  {
    py::gil_scoped_release release;
    auto lifted =
        std::make_shared<const NormalizedTask>(normalize(*domain.ast, *problem.ast, {domain.file, problem.file, {}}));
    PlanValidator validator(lifted, {epsilon, false});
    result = validator.validate(read.plan);
  }
  PyValidation out;
  out.valid = result.valid;
  out.makespan = result.makespan;
  out.value = result.value;
  out.metric = result.metric;
  out.cost = result.total_cost;
  out.happenings = result.happenings;
  if (result.violation) {
    const Violation& v = *result.violation;
    PyViolation pv;
    pv.kind = to_string(v.kind);
    pv.action = v.action;
    pv.condition = v.condition;
    pv.other_action = v.other_action;
    pv.message = v.message();
    pv.time = v.time;
    if (v.kind == Violation::Kind::UnsatisfiedInvariant) pv.until = v.until;
    if (v.line) pv.plan_line = v.line;
    out.violation = pv;
  }
  return out;
}

}  // namespace

PyDomain domain_of(const py::object& d) {
  if (py::isinstance<PyDomain>(d)) return d.cast<PyDomain>();
  const std::string path = py::str(d);
  return load_domain(read_text_file(path), path);
}

PyProblem problem_of(const py::object& p, const PyDomain& domain) {
  if (py::isinstance<PyProblem>(p)) return p.cast<PyProblem>();
  const std::string path = py::str(p);
  return load_problem(read_text_file(path), path, domain);
}

void add_planning(py::module_& m) {
  py::class_<PyStep>(m, "Step", "One step of a plan: start time, duration (None if instantaneous), action")
      .def_readonly("time", &PyStep::time)
      .def_readonly("duration", &PyStep::duration)
      .def_readonly("action", &PyStep::action)
      .def_readonly("args", &PyStep::args)
      .def_property_readonly("name", &PyStep::name)
      .def("__repr__", [](const PyStep& s) { return "<alplan.Step " + std::to_string(s.time) + ": " + s.name() + ">"; });
  py::class_<PyFoundPlan>(m, "FoundPlan", "A plan the planner found and validated")
      .def_readonly("steps", &PyFoundPlan::steps)
      .def_readonly("makespan", &PyFoundPlan::makespan)
      .def_readonly("metric", &PyFoundPlan::metric)
      .def_readonly("cost", &PyFoundPlan::cost)
      .def_readonly("seconds", &PyFoundPlan::seconds)
      .def_readonly("engine", &PyFoundPlan::engine)
      .def_readonly("text", &PyFoundPlan::text);
  py::class_<PyPlanResult>(m, "PlanResult",
                           "What plan() found: status, the best plan's steps and measures, every plan, statistics")
      .def_readonly("status", &PyPlanResult::status)
      .def_readonly("message", &PyPlanResult::message)
      .def_readonly("plans", &PyPlanResult::plans)
      .def_readonly("statistics", &PyPlanResult::statistics)
      .def_property_readonly("solved", [](const PyPlanResult& r) { return !r.plans.empty(); })
      .def_property_readonly("steps",
                             [](const PyPlanResult& r) { return r.plans.empty() ? std::vector<PyStep>{} : r.plans.back().steps; })
      .def_property_readonly("makespan", [](const PyPlanResult& r) {
        return r.plans.empty() ? std::optional<double>() : r.plans.back().makespan;
      })
      .def_property_readonly("metric", [](const PyPlanResult& r) {
        return r.plans.empty() ? std::optional<double>() : r.plans.back().metric;
      })
      .def_property_readonly("cost", [](const PyPlanResult& r) {
        return r.plans.empty() ? std::optional<double>() : r.plans.back().cost;
      })
      .def_property_readonly("text", [](const PyPlanResult& r) { return r.plans.empty() ? std::string() : r.plans.back().text; })
      .def("__repr__", [](const PyPlanResult& r) { return "<alplan.PlanResult " + r.status + ">"; });
  py::class_<PyViolation>(m, "Violation", "Why a plan is invalid, as VAL's error records say it")
      .def_readonly("kind", &PyViolation::kind)
      .def_readonly("time", &PyViolation::time)
      .def_readonly("until", &PyViolation::until)
      .def_readonly("action", &PyViolation::action)
      .def_readonly("condition", &PyViolation::condition)
      .def_readonly("other_action", &PyViolation::other_action)
      .def_readonly("plan_line", &PyViolation::plan_line)
      .def_readonly("message", &PyViolation::message)
      .def("__repr__", [](const PyViolation& v) { return "<alplan.Violation " + v.kind + ": " + v.message + ">"; });
  py::class_<PyValidation>(m, "ValidationResult", "valid, makespan, metric, value, cost, violation (or None)")
      .def_readonly("valid", &PyValidation::valid)
      .def_readonly("makespan", &PyValidation::makespan)
      .def_readonly("metric", &PyValidation::metric)
      .def_readonly("value", &PyValidation::value)
      .def_readonly("cost", &PyValidation::cost)
      .def_readonly("violation", &PyValidation::violation)
      .def_readonly("happenings", &PyValidation::happenings)
      .def("__bool__", [](const PyValidation& v) { return v.valid; });
  py::class_<PyGroundTask>(m, "GroundTask", "A grounded task: its size")
      .def_property_readonly("facts", [](const PyGroundTask& g) { return g.task->facts.size(); })
      .def_property_readonly("actions", [](const PyGroundTask& g) { return g.task->actions.size(); })
      .def_property_readonly("numeric_variables", [](const PyGroundTask& g) { return g.task->numeric.size(); })
      .def_property_readonly("timed_literals", [](const PyGroundTask& g) { return g.task->timed_literals.size(); })
      .def("action_names", [](const PyGroundTask& g) {
        std::vector<std::string> out;
        for (const GroundAction& a : g.task->actions) out.push_back(g.task->action_name(a));
        return out;
      });

  m.def("plan", &plan, py::arg("domain"), py::arg("problem"), py::arg("time_limit") = 60.0,
        "Plans a problem (files or parsed objects) in process. Options as keywords: search (ehc, gbfs, wastar, an "
        "alias or a configuration expression such as 'then(ehc(trpg), complete(wastar(trpg, w=1)))'; "
        "planner/README.md), alias, anytime, heuristic, weight, order (metric, steps), epsilon, reserve_planning_time, "
        "anytime_min_weight, anytime_expansions, ehc_expansions. Releases the GIL while it grounds and searches.");
  m.def("validate", &validate, py::arg("domain"), py::arg("problem"), py::arg("plan"), py::arg("epsilon") = 0.001,
        "Validates a plan (a PlanResult, plan text or a plan file) with VAL's semantics");
  m.def("ground",
        [](const py::object& d, const py::object& p) {
          const PyDomain domain = domain_of(d);
          const PyProblem problem = problem_of(p, domain);
          try {
            py::gil_scoped_release release;
            return PyGroundTask{alplan::ground(*domain.ast, *problem.ast, {{domain.file, problem.file, {}}, std::nullopt})};
          } catch (const GroundingError& e) {
            throw py::value_error(e.what());
          }
        },
        py::arg("domain"), py::arg("problem"), "Grounds a problem: facts, actions, numeric variables, timed literals");
}

}  // namespace alplan::python
