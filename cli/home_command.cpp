// `alplan home` (the running home, home/home_run.h; with --live fed by the
// wristbands in real time, home_live.h) and `alplan replay` (the same run
// again from its log's first line, compared event by event).
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdio>
#include <functional>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/home_run_options.h"
#include "cli/home_live.h"
#include "cli/perceive_common.h"
#include "cli/perception_module.h"
#include "home/event_log.h"
#include "home/home_run.h"
#include "planner/progress_meter.h"
#include "repair/repair_strategy.h"

namespace alplan::cli {
namespace {

struct HomeCommandOptions {
  home::HomeSettings settings = home::default_home_settings(ALPLAN_ASSISTED_LIVING_DIR);
  std::string home_file;
  std::string log;
  bool quiet = false;
  LiveFlags live;
  bool until_given = false, failure_chance_given = false;
};

// What a live run changes in the settings: no simulated seniors, no drawn
// failures unless asked for, a finer clock (stress is heard within a
// second), and plans that wait for their planning budget; until stopped
// when no --until.
void make_live(HomeCommandOptions& o) {
  home::HomeSettings& s = o.settings;
  s.live = true;
  s.script.clear();
  s.breakdowns.clear();  // a failure, scripted
  s.seniors.episodes_per_hour = 0.0;
  if (!o.failure_chance_given) s.failure_chance = 0.0;
  if (!o.until_given) s.until = 1e9;
  s.step_s = 1.0;
}

std::string one_line(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '\n' ? ' ' : c;
  return out;
}

// What a person watching the home wants to read, one line an event; the
// snaps and readings are in the log.
void narrate(const home::LogEvent& e) {
  const nlohmann::json& p = e.payload;
  const auto line = [&](const std::string& text) { std::printf("[%8.1f s] %s\n", e.time, text.c_str()); };
  if (e.type == "stress" && p.value("stressed", false)) line("stress: " + e.senior + "'s wristband says stressed");
  if (e.type == "goal") {
    line("goal " + p.value("goal", "") + ": " + p.value("motivation", "") + " (" + p.value("decided_by", "") +
         "), window until " + std::to_string(static_cast<long>(p.value("window_end", 0.0))) + " s");
  }
  if (e.type == "plan") {
    line("plan " + std::to_string(p.value("plan_id", 0)) + " (" + p.value("reason", "") + ", mission " +
         std::to_string(p.value("mission", 0)) + "):");
    std::printf("%s", p.value("plan", "").c_str());
  }
  if (e.type == "failure") line("failure: " + p.value("action", "") + ": " + p.value("condition", ""));
  if (e.type == "repair") {
    line(std::string("repair by ") + p.value("strategy", "") + (p.value("repaired", false) ? ": " : " failed: ") +
         one_line(p.value("how", "")));
  }
  if (e.type == "explanation") {
    line("explanation: why: " + one_line(p.value("why", "")) + " | what: " + one_line(p.value("what", "")) +
         " | how: " + one_line(p.value("how", "")));
  }
  if (e.type == "comforted") {
    line(e.senior + " comforted: " + p.value("goal", "") + (p.value("within_window", false) ? ", within the window" : ", too late"));
  }
  if (e.type == "battery") {
    char text[160];
    std::snprintf(text, sizeof text, "%s's battery: %.2f now, lowest %.2f, reserve %.2f%s", e.robot.c_str(),
                  p.value("level", 0.0), p.value("lowest", 0.0), p.value("reserve", 0.0),
                  p.value("below_reserve", false) ? ": WENT BELOW ITS RESERVE" : "");
    line(text);
  }
  if (e.type == "robot_down") line(e.robot + " reports a fault: out of service");
  if (e.type == "robot_up") line(e.robot + " is back in service");
  if (e.type == "window_passed") line(e.senior + "'s window passed before " + p.value("goal", "") + ": served late");
  if (e.type == "window_missed") line(e.senior + "'s window closed before " + p.value("goal", "") + ": looking again");
}

void print_summary(const home::HomeSummary& s, bool live) {
  std::printf("\nsummary: %zu goals, %zu comforted (%zu within their windows), %zu windows missed\n", s.goals,
              s.comforted, s.within_window, s.windows_missed);
  std::printf("         %zu plans (%zu merges), %zu failures, repairs:", s.plans, s.merges, s.failures);
  for (const auto& [strategy, n] : s.repairs) std::printf(" %s %zu", strategy.c_str(), n);
  std::printf(", %zu failed\n", s.repairs_failed);
  for (const auto& [robot, b] : s.batteries) {
    std::printf("         %s's battery: lowest %.2f, reserve %.2f, %s\n", robot.c_str(), b.lowest, b.reserve,
                b.below_reserve ? "went below its reserve" : "never below its reserve");
  }
  const nlohmann::json j = s.json();
  // Nearest ranks over every call, failed ones included; none without a call.
  const auto seconds = [&](const char* key) {
    if (j[key].is_null()) return std::string("-");
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", j[key].get<double>());
    return std::string(text);
  };
  const std::string p50 = seconds("planning_p50_s"), p95 = seconds("planning_p95_s");
  if (live) {
    std::printf("         planning p50 %s s, p95 %s s (every call); %.1f s of wall time\n", p50.c_str(), p95.c_str(),
                s.end_time);
    return;
  }
  std::printf("         planning p50 %s s, p95 %s s (every call); scored against the simulation: %zu stress episodes, "
              "%zu detected, %zu false alarms\n",
              p50.c_str(), p95.c_str(), s.episodes, s.episodes_detected, s.false_alarms);
}

int run_home_command(HomeCommandOptions& o) {
  // The default home's script, breakdown and devices name its seniors,
  // robots and rooms: another home has none of them.
  const auto another_home = [&o] {
    o.settings.script.clear();
    o.settings.breakdowns.clear();
    o.settings.devices.clear();
  };
  if (!o.home_file.empty()) {
    o.settings.home_file = o.home_file;
    another_home();
  }
  if (o.settings.generate_seniors > 0) another_home();
  check_live_flags(o.live);
  if (o.live.live) {
    make_live(o);
    const home::HomeSummary summary =
        run_live_home(o.settings, o.live, o.log, o.quiet ? home::EventLog::Echo{} : narrate);
    print_summary(summary, true);
    if (!o.log.empty()) std::printf("log: %s\n", o.log.c_str());
    return kExitOk;
  }
  std::ofstream file;
  if (!o.log.empty()) {
    file.open(o.log, std::ios::binary | std::ios::trunc);
    if (!file) throw std::invalid_argument(o.log + ": cannot write the log");
  }
  home::EventLog log(o.log.empty() ? nullptr : &file, o.quiet ? home::EventLog::Echo{} : narrate);
  // Narrated runs show the time in every line; a quiet one gets a meter.
  ProgressMeter meter(std::cerr, o.settings.until, "simulated s", isatty(STDERR_FILENO) != 0);
  const home::HomeSummary summary =
      home::run_home(o.settings, log, o.quiet ? simulated_time_meter(meter) : std::function<void(double)>{});
  meter.finish();
  print_summary(summary, false);
  if (!o.log.empty()) std::printf("log: %s (%zu events)\n", o.log.c_str(), log.events().size());
  return kExitOk;
}

int run_replay(const std::string& path) {
  const home::LogReading logged = home::read_event_log(path);
  for (const std::string& w : logged.warnings) std::cerr << "warning: " << w << "\n";
  const nlohmann::json& first = logged.events.front();
  if (first.value("type", "") != "observation" || first.value("what", "") != "home" || !first.contains("settings")) {
    throw std::invalid_argument(path + ":" + std::to_string(logged.lines.front()) +
                                ": the first event is not the home's observation with the run's settings");
  }
  const home::HomeSettings settings = home::HomeSettings::from_json(first["settings"]);
  if (settings.live) throw CommandInputError("a live run cannot be replayed: its inputs came from wristbands");
  home::EventLog replayed;
  home::run_home(settings, replayed);
  if (const auto difference = home::first_difference(logged, replayed.events())) {
    std::printf("replay differs from %s: %s\n", path.c_str(), difference->c_str());
    return kExitInvalid;
  }
  std::printf("replay of %s: the same %zu events (goals, plans, actions, failures, repairs, outcomes)\n", path.c_str(),
              replayed.events().size());
  return logged.warnings.empty() ? kExitOk : kExitInvalid;
}

}  // namespace

void add_home_command(CLI::App& app, int& exit_code) {
  auto o = std::make_shared<HomeCommandOptions>();
  CLI::App* cmd = app.add_subcommand("home", kHomeHelp);
  home::HomeSettings& s = o->settings;
  cmd->add_option("--home", o->home_file,
                  "A home's problem file for domains/assisted_living/domain.pddl (--battery: battery/domain.pddl; "
                  "its goal is ignored)");
  cmd->add_option("--seniors", s.generate_seniors, "Generate a home with this many seniors (alplan gen home)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--robots", s.generate_robots, "Robots of the generated home")->check(CLI::Range(1, 100));
  cmd->add_option("--rooms", s.generate_rooms, "Rooms of the generated home")->check(CLI::Range(4, 1000));
  cmd->add_option("--objects", s.generate_objects, "Portable objects of the generated home")->check(CLI::Range(1, 10000));
  cmd->add_option("--strategy", s.strategy, "Repair strategy: " + repair::strategy_list());
  cmd->add_option("--observe", s.observe, "What the robots see: full, iot, camera (repair/observation.h)");
  cmd->add_option("--until", s.until, "Simulated seconds to run (--live: wall seconds; default until SIGINT/SIGTERM)")->check(CLI::Range(0.0, 7.0 * 24 * 3600));
  cmd->add_option("--seed", s.seed, "Seed of the seniors, the failures and a generated home");
  add_home_run_options(*cmd, s);
  cmd->add_option("--log", o->log, "Write the event log here (JSON Lines)");
  cmd->add_flag("--quiet", o->quiet, "Print the summary only");
  cmd->add_option("--planning-time", s.planning_time,
                  "Seconds a plan may take (--live: and no step starts before they pass)")
      ->check(CLI::Range(0.1, 600.0));
  add_live_flags(*cmd, o->live);
  cmd->callback([o, cmd, &exit_code] {
    o->until_given = cmd->count("--until") > 0;
    o->failure_chance_given = cmd->count("--failure-chance") > 0;
    exit_code = guarded([&] { return run_home_command(*o); }, "the home");
  });

  auto log = std::make_shared<std::string>();
  CLI::App* replay = app.add_subcommand("replay", kReplayHelp);
  replay->add_option("LOG", *log, "The event log of alplan home --log")->required();
  replay->callback([log, &exit_code] { exit_code = guarded([&] { return run_replay(*log); }, *log); });
}

}  // namespace alplan::cli
