#include "domains/paper_scenarios.h"

#include <stdexcept>

#include "domains/pddl_files.h"
#include "repair/reformulation.h"
#include "repair/type_ontology.h"

namespace alplan::domains {

std::vector<PaperScenario> paper_scenarios() {
  using repair::becomes_unavailable;
  using repair::object_appears;
  std::vector<PaperScenario> all(3);
  all[0].name = "paper-1";
  all[0].problem_file = "paper-scenario-1.pddl";
  all[0].motivation = "senior1 is stressed and terrified, so the robot brings water";
  for (int g = 1; g <= 8; ++g) all[0].events.push_back(becomes_unavailable(140.007, "glass_id0" + std::to_string(g)));
  all[0].events.push_back(object_appears(140.007, {"mug_id01", "mug", "kitchen1", 1.0}));
  all[0].initial_figure = "Fig. 6";
  all[0].repaired_figure = "Fig. 7";

  all[1].name = "paper-2";
  all[1].problem_file = "paper-scenario-2.pddl";
  all[1].motivation = "senior1 is stressed and sad, so the robot brings music";
  all[1].events = {becomes_unavailable(120.005, "violin_id01"), becomes_unavailable(120.005, "guitar_id01"),
                   object_appears(120.005, {"clarinet_id01", "clarinet", "music_room1", 1.0})};
  all[1].initial_figure = "Fig. 8";
  all[1].repaired_figure = "Fig. 9";

  all[2].name = "paper-3";
  all[2].problem_file = "paper-scenario-3.pddl";
  all[2].motivation = "senior1 is stressed and bored, so the robot brings entertainment";
  all[2].events = {becomes_unavailable(0.0, "book_id01"), becomes_unavailable(0.0, "magazine_id01")};
  all[2].initial_figure = "Fig. 10";
  all[2].repaired_figure = "Fig. 11";
  return all;
}

ScenarioRun run_paper_scenario(const PaperScenario& scenario, const ScenarioOptions& options) {
  const std::string dir = options.assisted_living_dir;
  const LoadedFiles files = load_pddl(dir + "/domain.pddl", dir + "/" + scenario.problem_file);
  const repair::TypeOntology ontology = repair::TypeOntology::from_file(dir + "/types.ttl");
  const pddl::Domain domain = repair::augment_domain(*files.domain, ontology);

  ScenarioRun run;
  run.scenario = scenario;
  // The first plan is the best the planner can prove within its time: the
  // metric penalises suggestions, and the first plan found may suggest.
  PlannerOptions initial;
  initial.epsilon = options.epsilon;
  initial.anytime = true;
  initial.time_limit = options.planning_time;
  const repair::PlanningOutcome planned = repair::plan_in_process(domain, *files.problem, 0.0, initial);
  if (!planned.plan) throw std::runtime_error(scenario.name + ": no initial plan: " + planned.message);
  run.initial_plan = repair::plan_text(*planned.plan);
  run.initial_planning_seconds = planned.seconds;

  repair::StrategyOptions strategy_options;
  strategy_options.planner.epsilon = options.epsilon;
  strategy_options.planner.time_limit = options.planning_time;
  std::unique_ptr<repair::RepairStrategy> strategy = repair::make_strategy(options.strategy, strategy_options);
  std::vector<repair::ExogenousEvent> events = repair::timed_literal_events(*files.problem);
  events.insert(events.end(), scenario.events.begin(), scenario.events.end());
  repair::WorldSimulator world(repair::initial_world(*files.problem), events);
  repair::Mission mission;
  mission.domain = &domain;
  mission.problem = *files.problem;
  mission.motivation = scenario.motivation;
  mission.goal_generator = emotion_goal_generator("senior1");
  const repair::Monitor monitor(options.monitor);
  run.report = monitor.run(mission, *planned.plan, world, *strategy, &world, &ontology);
  for (const repair::ExogenousEvent& e : world.applied()) run.applied_events.push_back(e.description);
  return run;
}

}  // namespace alplan::domains
