// The three scenarios of the paper's Section 7.1, end to end: the initial
// plan (Figs. 6, 8, 10), the exogenous events, the failure the monitor
// detects and the repaired plan (Figs. 7, 9, 11), with explanations.
//
// Scripted events (the paper says what happens, not exactly when), met as
// the paper's robot meets them under the default observation model (iot):
// 1. a mug stands in the kitchen from the start; every glass becomes
//    unavailable at 125, while the robot walks from the dining room to the
//    kitchen. The glasses' IoT tags report it at once and the look-ahead
//    foresees the failure, but nothing known can replace them, so the
//    robot carries on; at 140.008 it is in the kitchen, its camera sees
//    the mug, the carry's condition is due and fails, and substitution
//    repairs with the mug (Fig. 7);
// 2. likewise a clarinet in the music room, the instruments unavailable at
//    100 while the robot walks there, met at 120.006 (Fig. 9);
// 3. the book and the magazine become unavailable as execution begins, and
//    nothing new appears: the monitor's look-ahead sees at once that the
//    book will not be there, and the repair falls back on a suggestion.
// OPTIC's plans in the paper separate dependent happenings by 0.002; the
// scenarios plan with that separation so that the times match the figures.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "domains/mission_run.h"
#include "repair/monitor.h"
#include "repair/world_simulator.h"

namespace alplan::domains {

struct PaperScenario {
  std::string name;          // "paper-1"
  std::string problem_file;  // in domains/assisted_living/
  std::string motivation;
  std::vector<repair::ExogenousEvent> events;
  std::string initial_figure, repaired_figure;
};

std::vector<PaperScenario> paper_scenarios();


struct ScenarioRun : MissionRun {
  PaperScenario scenario;
};

// Throws domains::InputError on unreadable input, std::runtime_error when
// the initial problem has no plan.
ScenarioRun run_paper_scenario(const PaperScenario& scenario, const ScenarioOptions& options);

}  // namespace alplan::domains
