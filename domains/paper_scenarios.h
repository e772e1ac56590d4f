// The three scenarios of the paper's Section 7.1, end to end: the initial
// plan (Figs. 6, 8, 10), the exogenous events, the failure the monitor
// detects and the repaired plan (Figs. 7, 9, 11), with explanations.
//
// Scripted events (the paper says what happens, not exactly when):
// 1. every drinking vessel becomes unavailable as the robot reaches the
//    kitchen (140.007) and a mug appears there;
// 2. the music instruments become unavailable as the robot reaches the music
//    room (120.005) and a clarinet appears there;
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
