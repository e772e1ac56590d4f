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
  cmd.add_option("--fleet", s.fleet,
                 "allocate: a mission per robot, several at once, each goal to the robot with the least weighted "
                 "lateness; dispatch: one mission at a time, new goals merged into it")
      ->check(CLI::IsMember({"allocate", "dispatch"}));
  cmd.add_option_function<std::vector<double>>(
         "--urgency-weights",
         [&s](const std::vector<double>& w) {
           s.terrified_weight = w.at(0);
           s.sad_weight = w.at(1);
           s.bored_weight = w.at(2);
         },
         "Urgency weights of terrified, sad and bored seniors: of lateness in the allocation, of a window missed "
         "in the plan's metric (default 3 2 1)")
      ->expected(3)
      ->check(CLI::Range(0.0, 1e4));
  cmd.add_flag("!--hard-windows", s.soft_windows,
               "Comfort windows as hard deadlines that close (a goal no plan meets in time is dropped), not as "
               "PDDL 3 preferences weighted by urgency");
  cmd.add_option("--window-cost", s.window_cost_s,
                 "A window missed costs its urgency weight times this many seconds of the plan's metric")
      ->check(CLI::Range(0.0, 1e7));
  cmd.add_option("--failure-kinds", s.failure_kinds,
                 "Kinds of the failures drawn against new plans: the repair study's (sibling arrival iot moves "
                 "overrun emotion two) and robot_down")
      ->expected(1, 16);
  cmd.add_option("--robot-repair", s.robot_repair_s,
                 "Seconds a broken-down robot (failure kind robot_down) is out of service")
      ->check(CLI::Range(0.0, 1e7));
  cmd.add_option("--breakdown-rate", s.breakdown_rate_per_hour,
                 "Breakdowns per robot and simulated hour in service, at random times (a Poisson process), besides "
                 "drawn and scripted ones; each out of service --robot-repair seconds (default 0: none)")
      ->check(CLI::Range(0.0, 100.0));
  cmd.add_flag("!--no-dispatch", s.dispatch,
               "With --fleet dispatch: plan each mission with every robot, not the nearest one per senior");
  add_battery_options(cmd, s);
}

void add_battery_options(CLI::App& cmd, home::HomeSettings& s) {
  CLI::Option* battery = cmd.add_flag(
      "--battery", s.battery,
      "Robots with batteries: moves drain them, a dock recharges them (domains/assisted_living/battery/)");
  domains::BatteryOptions& b = s.battery_options;
  const auto level = [&](const char* name, double& value, const char* what) {
    cmd.add_option(name, value, what)->check(CLI::NonNegativeNumber)->needs(battery);
  };
  level("--battery-capacity", b.capacity, "A full battery (with --battery; default 100)");
  level("--battery-reserve", b.reserve, "The level no planned move may go below (with --battery; default 20)");
  level("--battery-initial", b.initial, "Each robot's level at the start (with --battery; default 100)");
  level("--battery-drain", b.drain_rate, "Drain per second of moving (with --battery; default 0.05)");
  level("--battery-charge", b.charge_rate, "Charge per second at the dock (with --battery; default 0.5)");
}

}  // namespace alplan::cli
