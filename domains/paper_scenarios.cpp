#include "domains/paper_scenarios.h"

#include <stdexcept>

#include "domains/mission_run.h"
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
  for (int g = 1; g <= 8; ++g) all[0].events.push_back(becomes_unavailable(125.0, "glass_id0" + std::to_string(g)));
  all[0].events.push_back(object_appears(0.0, {"mug_id01", "mug", "kitchen1", 1.0}));
  all[0].initial_figure = "Fig. 6";
  all[0].repaired_figure = "Fig. 7";

  all[1].name = "paper-2";
  all[1].problem_file = "paper-scenario-2.pddl";
  all[1].motivation = "senior1 is stressed and sad, so the robot brings music";
  all[1].events = {becomes_unavailable(100.0, "violin_id01"), becomes_unavailable(100.0, "guitar_id01"),
                   object_appears(0.0, {"clarinet_id01", "clarinet", "music_room1", 1.0})};
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
  const LoadedHome home = load_home(options.assisted_living_dir, scenario.problem_file);
  MissionInput input;
  input.domain = &home.domain;
  input.problem = *home.files.problem;
  input.events = scenario.events;
  input.motivation = scenario.motivation;
  input.seniors = {"senior1"};
  input.ontology = &home.ontology;
  ScenarioRun run;
  static_cast<MissionRun&>(run) = run_mission(input, options);
  run.scenario = scenario;
  return run;
}

}  // namespace alplan::domains
