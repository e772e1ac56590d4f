// The execution monitor against a world written in Python: an object with
// advance(t), observe(), start_action(name, t, duration) and
// end_action(name, t) -> bool. observe() returns {"atoms": [...], "values":
// {...}}, atoms and function terms written as PDDL, "(at b1 r2)". The
// monitor runs with the GIL held: it calls the world at every observation.
#include <sstream>

#include <nlohmann/json.hpp>
#include <pybind11/stl.h>

#include "python/bindings.h"
#include "repair/monitor.h"
#include "repair/reformulation.h"
#include "repair/world.h"

namespace alplan::python {
namespace {

repair::AtomKey key_of(const std::string& text) {
  std::string cleaned = text;
  for (char& c : cleaned) {
    if (c == '(' || c == ')') c = ' ';
  }
  std::istringstream in(cleaned);
  repair::AtomKey key;
  for (std::string w; in >> w;) {
    for (char& c : w) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    key.push_back(w);
  }
  if (key.empty()) throw py::value_error("observe(): an empty atom '" + text + "'");
  return key;
}

py::object to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

class PythonWorld : public repair::World {
 public:
  explicit PythonWorld(py::object world) : world_(std::move(world)) {}

  void advance(double t) override { world_.attr("advance")(t); }

  repair::WorldState observe() const override {
    const py::dict seen = world_.attr("observe")();
    repair::WorldState state;
    if (seen.contains("atoms")) {
      for (const py::handle atom : seen["atoms"]) state.atoms.insert(key_of(py::str(atom)));
    }
    if (seen.contains("values")) {
      for (const auto& [term, value] : seen["values"].cast<py::dict>()) {
        state.values[key_of(py::str(term))] = value.cast<double>();
      }
    }
    if (seen.contains("time")) state.time = seen["time"].cast<double>();
    return state;
  }

  void start_action(const GroundTask& task, ActionId action, double t, double duration) override {
    const GroundAction& a = task.actions[action];
    const std::string name = task.action_name(a);
    world_.attr("start_action")(name, t, duration);
    if (!a.durative) return;
    repair::ActionInProgress p;
    p.name = name;
    p.expected_end = t + duration;
    const repair::StateMapping mapping(task);
    for (FactId f : a.end.add) p.adds.push_back(mapping.fact_key(f));
    for (FactId f : a.end.del) p.dels.push_back(mapping.fact_key(f));
    running_[name] = p;
  }

  bool end_action(const GroundTask& task, ActionId action, double t) override {
    const std::string name = task.action_name(task.actions[action]);
    const bool ended = world_.attr("end_action")(name, t).cast<bool>();
    if (ended) running_.erase(name);
    return ended;
  }

  std::vector<repair::ActionInProgress> in_progress() const override {
    std::vector<repair::ActionInProgress> out;
    for (const auto& [name, a] : running_) out.push_back(a);
    return out;
  }

 private:
  py::object world_;
  std::map<std::string, repair::ActionInProgress> running_;
};

py::object execute(const py::object& domain_arg, const py::object& problem_arg, const py::object& world,
                   const std::string& strategy, const std::string& observe, const std::string& robot,
                   double epsilon, double time_limit) {
  const PyDomain domain = domain_of(domain_arg);
  const PyProblem problem = problem_of(problem_arg, domain);
  const std::optional<repair::ObservationModel> model = repair::observation_model(observe);
  if (!model) throw py::value_error("observe must be full, iot or camera, not '" + observe + "'");
  repair::StrategyOptions strategy_options;
  strategy_options.planner.epsilon = epsilon;
  strategy_options.planner.time_limit = time_limit;
  std::unique_ptr<repair::RepairStrategy> repairer;
  try {
    repairer = repair::make_strategy(strategy, strategy_options);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  PlannerOptions initial = repair::executing_planner_options();
  initial.epsilon = epsilon;
  initial.time_limit = time_limit;
  const repair::PlanningOutcome planned = repair::plan_in_process(*domain.ast, *problem.ast, 0.0, initial);
  if (!planned.plan) throw py::value_error("no initial plan: " + planned.message);
  repair::Mission mission;
  mission.domain = domain.ast.get();
  mission.problem = *problem.ast;
  mission.robot = robot;
  repair::MonitorOptions options;
  options.observation.model = *model;
  PythonWorld adapter(world);
  const repair::ExecutionReport report =
      repair::Monitor(options).run(mission, *planned.plan, adapter, *repairer, nullptr, nullptr);
  return to_python(report.json());
}

}  // namespace

void add_monitor(py::module_& m) {
  m.def("strategies", &repair::strategy_names, "The repair strategies by name");
  m.def("execute", &execute, py::arg("domain"), py::arg("problem"), py::arg("world"), py::arg("strategy") = "replan",
        py::arg("observe") = "full", py::arg("robot") = "robot1", py::arg("epsilon") = 0.001,
        py::arg("time_limit") = 10.0,
        "Plans the problem, then executes the plan under the monitor against `world` (advance(t), observe(), "
        "start_action(name, t, duration), end_action(name, t) -> bool), repairing failures with the named "
        "strategy. Returns the execution report as a dict: goal_reached, outcome, end_time, events, repairs "
        "(each with its three-part explanation), initial_plan.");
}

}  // namespace alplan::python
