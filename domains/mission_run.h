// One mission of the assisted-living robot end to end: plan the problem,
// execute the plan against a simulated world with scripted exogenous events,
// and let the monitor detect failures and repair them with a strategy. The
// paper's scenarios and `alplan deliberate` (perception's goal, a camera's
// objects) both run through here.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "domains/pddl_files.h"
#include "repair/monitor.h"
#include "repair/object_recognizer.h"
#include "repair/repair_strategy.h"
#include "repair/type_ontology.h"
#include "repair/world_simulator.h"

namespace alplan::domains {

// How a mission runs: the planner's separation and budget, the repair
// strategy, the monitor.
struct ScenarioOptions {
  std::string assisted_living_dir;  // domains/assisted_living
  std::string strategy = "substitute";
  double epsilon = 0.002;
  double planning_time = 10.0;  // per planner call, seconds
  // The strategy's own knobs (adapt's search); its planner's epsilon and
  // time come from the two fields above.
  repair::StrategyOptions strategy_options;
  repair::MonitorOptions monitor;
};

// A home as the missions read it: the domain and a problem from `dir`, and
// the type ontology (`dir`/types.ttl) whose augmented types the domain gets.
struct LoadedHome {
  LoadedFiles files;
  repair::TypeOntology ontology;
  pddl::Domain domain;  // files.domain with the ontology's types
};

// What a home's IoT reports change without the robot: an object becoming
// unavailable (taken, broken). Seniors' places and emotions change too, but
// the domain's actions already change those predicates.
std::vector<std::string> exogenous_predicates();

// Throws domains::InputError (or repair::OntologyError) naming the file.
LoadedHome load_home(const std::string& dir, const std::string& problem_file);
// The same with each file named: a variant of the domain (battery/domain.pddl)
// with the home's ontology.
LoadedHome load_home_files(const std::string& domain_file, const std::string& problem_file,
                           const std::string& ontology_file);

struct MissionInput {
  const pddl::Domain* domain = nullptr;  // with the ontology's types (augment_domain)
  pddl::Problem problem;
  std::vector<repair::ExogenousEvent> events;  // besides the problem's timed literals
  std::string motivation;                      // why the goal: "senior1 is stressed and terrified"
  std::vector<std::string> seniors;            // whose emotions goal generation reads
  const repair::TypeOntology* ontology = nullptr;
  // What perception sees on request; null: the simulator's own report of
  // the objects its events made appear.
  repair::ObjectRecognizer* recognizer = nullptr;
};

struct MissionRun {
  std::string initial_plan;  // IPC format
  double initial_planning_seconds = 0.0;
  repair::ExecutionReport report;
  std::vector<std::string> applied_events;
};

// The home offers no plan for the goal at all (for example no object that
// cheers a sad senior): an outcome of deliberation, not an input error.
class NoInitialPlan : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws NoInitialPlan when the problem has no initial plan.
MissionRun run_mission(const MissionInput& input, const ScenarioOptions& options);

}  // namespace alplan::domains
