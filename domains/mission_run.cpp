#include "domains/mission_run.h"

#include <memory>
#include <stdexcept>

#include "domains/emotion_goals.h"
#include "repair/reformulation.h"

namespace alplan::domains {

LoadedHome load_home(const std::string& dir, const std::string& problem_file) {
  return load_home_files(dir + "/domain.pddl", dir + "/" + problem_file, dir + "/types.ttl");
}

LoadedHome load_home_files(const std::string& domain_file, const std::string& problem_file,
                           const std::string& ontology_file) {
  LoadedFiles files = load_pddl(domain_file, problem_file);
  repair::TypeOntology ontology = repair::TypeOntology::from_file(ontology_file);
  pddl::Domain domain = repair::augment_domain(*files.domain, ontology);
  return {std::move(files), std::move(ontology), std::move(domain)};
}

std::vector<std::string> exogenous_predicates() { return {"available"}; }

MissionRun run_mission(const MissionInput& input, const ScenarioOptions& options) {
  MissionRun run;
  // The first plan is the best the planner can prove within its time: the
  // metric penalises suggestions, and the first plan found may suggest.
  PlannerOptions initial = repair::executing_planner_options();
  initial.epsilon = options.epsilon;
  initial.search = alias("anytime");
  initial.time_limit = options.planning_time;
  const repair::PlanningOutcome planned = repair::plan_in_process(*input.domain, input.problem, 0.0, initial);
  if (!planned.plan) throw NoInitialPlan(input.problem.name + ": no initial plan: " + planned.message);
  run.initial_plan = repair::plan_text(*planned.plan);
  run.initial_planning_seconds = planned.seconds;

  repair::StrategyOptions strategy_options = options.strategy_options;
  strategy_options.planner.epsilon = options.epsilon;
  strategy_options.planner.time_limit = options.planning_time;
  std::unique_ptr<repair::RepairStrategy> strategy = repair::make_strategy(options.strategy, strategy_options);
  std::vector<repair::ExogenousEvent> events = repair::timed_literal_events(input.problem);
  events.insert(events.end(), input.events.begin(), input.events.end());
  repair::WorldSimulator world(repair::initial_world(input.problem), events);
  repair::Mission mission;
  mission.domain = input.domain;
  mission.problem = input.problem;
  mission.motivation = input.motivation;
  mission.exogenous_predicates = exogenous_predicates();
  mission.goal_generator = input.seniors.size() == 1 ? emotion_goal_generator(input.seniors.front())
                                                     : emotion_goal_generator(input.seniors);
  const repair::Monitor monitor(options.monitor);
  repair::ObjectRecognizer* eyes = input.recognizer ? input.recognizer : &world;
  run.report = monitor.run(mission, *planned.plan, world, *strategy, eyes, input.ontology);
  for (const repair::ExogenousEvent& e : world.applied()) run.applied_events.push_back(e.description);
  return run;
}

}  // namespace alplan::domains
