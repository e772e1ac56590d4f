#include "cli/home_run_options.h"

namespace alplan::cli {

void add_home_run_options(CLI::App& cmd, home::HomeSettings& s) {
  cmd.add_option("--drift", s.seniors.drift_bpm, "Seniors' resting heart rate swinging slowly by up to this many bpm")
      ->check(CLI::Range(0.0, 40.0));
  cmd.add_option("--episodes-per-hour", s.seniors.episodes_per_hour, "Stress episodes per senior and hour (drawn homes)")
      ->check(CLI::Range(0.0, 60.0));
  cmd.add_option("--stress-follow", s.stress_follow_readings,
                 "Readings the stress detector's baseline follows a calm senior over")
      ->check(CLI::Range(1, 100000));
  cmd.add_option("--failure-chance", s.failure_chance, "Chance that a new plan meets a drawn failure")
      ->check(CLI::Range(0.0, 1.0));
  cmd.add_option("--planner-expansions", s.planner_expansions,
                 "Anytime improvement: expansions per weight (deterministic); 0: the first plan");
  cmd.add_option("--planner-node-limit", s.planner_node_limit,
                 "Nodes a planner call may store before it gives up (deterministic, unlike the time limit)");
  cmd.add_option("--replan-expansions", s.replan_expansions,
                 "Anytime improvement of repairs' and merges' plans: expansions per weight; 0: the first plan");
  cmd.add_option("--object-return", s.object_return_s,
                 "Seconds until an object taken away or handed to a senior is back in its place (0: never)")
      ->check(CLI::NonNegativeNumber);
  cmd.add_flag("!--no-dispatch", s.dispatch, "Plan each mission with every robot, not the nearest one per senior");
}

}  // namespace alplan::cli
