// The problems a running home plans with: its home loaded (a file or a
// generated home, with batteries when asked), the home at rest, and what a
// mission adds (each robot able to reach a dock at its end).
#pragma once

#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "domains/battery_home.h"
#include "domains/mission_run.h"
#include "home/goal_source.h"
#include "home/home_map.h"
#include "home/home_settings.h"
#include "pddl_parser/ast.h"
#include "planner/planner.h"
#include "repair/executing_plan.h"
#include "repair/observation.h"
#include "repair/random_events.h"
#include "repair/world_state.h"

namespace alplan::home {

struct LoadedRun {
  domains::LoadedHome home;
  HomeMap map;
};

// Throws the loaders' errors naming the file.
LoadedRun load_run(const HomeSettings& settings);

// The home's problem with nothing to do: no emotion, window or goal yet.
pddl::Problem calm_problem(const pddl::Problem& problem);

// The robot a ground action names ("(move robot1 a b)"), or "".
std::string robot_of(const std::string& action, const HomeMap& map);

// A plan's steps for the log: start, duration, action and robot, and the
// device for a device's action.
nlohmann::json steps_json(const repair::ExecutingPlan& plan, const HomeMap& map, const std::set<std::string>& devices);

// With batteries, each robot of a mission must end it able to reach a
// dock (domains::return_levels): the domain's reserve keeps plans safe,
// this keeps a robot from being left at its reserve far from the dock,
// where it could not move at all (home/README.md, Batteries).
void require_return(pddl::Problem& problem, const std::vector<std::string>& robots,
                    const std::map<std::string, double>& return_levels);

// What the robots see (--observe); throws std::invalid_argument naming a
// model that is not full, iot or camera.
repair::ObservationOptions home_observation_options(const HomeSettings& settings);
// The failures drawn against new plans: the repair study's kinds among
// settings.failure_kinds (robot_down is the home's own, robot_faults.h);
// throws std::invalid_argument naming a kind that is neither.
repair::RandomEventOptions home_event_options(const HomeSettings& settings);

// How the home plans a mission's first plan, and its repairs and merges.
PlannerOptions home_planner_options(const HomeSettings& settings);
PlannerOptions home_replanner_options(const HomeSettings& settings);

// Writes the problem as an external planner would get it, time 0 being
// `now` (the home plans from now in the task's own time), so that `alplan
// plan` on DIR/unplanned-N.pddl meets the same deadlines; the first also
// writes DIR/domain.pddl.
void write_unplanned(const std::string& dir, int n, const pddl::Problem& problem, const pddl::Domain& domain,
                     double now);

// What a new goal tells the world and the robots: the emotion read, the
// goal not yet reached, the window open.
std::vector<std::pair<repair::AtomKey, bool>> told_facts(const PerceivedGoal& goal);
// A type of the home's devices, whose actions need no robot: speaker,
// lamp, tv.
bool is_device_type(const std::string& type);

// The device of the senior's believed room that answers their emotion (a
// speaker for the terrified, a lamp for the sad, an available TV for the
// bored), if any.
std::optional<std::string> answering_device(const PerceivedGoal& goal, const pddl::Problem& home,
                                           const repair::WorldState& believed);
// The goal asks for the device's answer too: (and GOAL (reassured SENIOR)).
void ask_device_response(PerceivedGoal& goal);
// And no longer (the senior left the device's room, or its answer was
// given): the goal as perceived. Nothing when it asked for none.
void drop_device_response(PerceivedGoal& goal);
// The device a ground action is done by, "(play_calming_music speaker1 ...)"
// -> "speaker1"; "" for the robots' actions.
std::string device_of(const std::string& action, const std::set<std::string>& devices);

// The literal that closes the goal's window (hard windows).
pddl::TimedInitialLiteral window_close(const PerceivedGoal& goal);

// What travel estimates need of a believed state: where things are, the
// paths and their times.
pddl::Problem believed_places(const repair::WorldState& believed);

// Urgency as PDDL 3 preferences (HomeSettings::soft_windows): for each goal
// whose window is still open at `now`, (preference late-SENIOR (within END
// GOAL)), its violation costing weight_of(emotion) * window_cost_s in the
// problem's metric beside what the metric already counts. A window already
// passed leaves nothing to prefer (its violation is a constant). No open
// window: the problem's constraints are none and its metric is `base`.
void prefer_windows(pddl::Problem& problem, const std::optional<pddl::Metric>& base,
                    const std::vector<PerceivedGoal>& goals, double now, const HomeSettings& settings);

}  // namespace alplan::home
