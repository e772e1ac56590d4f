// What the monitor acts on and observes. The monitor dispatches the plan's
// snaps to it (the robot acting) and reads observed states from it; how the
// world really evolves is its own business — a simulator with exogenous
// events for experiments, or a home's IoT readings and a robot in service.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "planner/ground_task.h"
#include "repair/world_state.h"

namespace alplan::repair {

// An action the robot has started and the world has not yet seen end, with
// the world's estimate of when it will.
struct ActionInProgress {
  std::string name;
  double expected_end = 0.0;
  std::vector<AtomKey> adds, dels;  // what its end will change
  // Its continuous effects (PDDL 2.1 linear change): each value it moves
  // and by how much per second, signed, fixed when it started. A replan
  // needs them: the change goes on until the action ends.
  std::vector<std::pair<AtomKey, double>> rates;
};

// One of the robot's actions that came to nothing (world_simulator.h), and
// the literal of its condition that stopped it, with the value it had: what
// the robot's executive learns when an action aborts (a grasp that closes
// on nothing, a handover no one takes).
struct VoidAction {
  double time = 0.0;
  std::string action;  // "(give robot1 senior1 violin_id01 sunroom1)"
  AtomKey literal;     // empty for a derived fact, which the world keeps no record of
  bool holds = false;  // the literal's value in the world
  std::string why;     // "(be senior1 sunroom1) did not hold at its start"
};

class World {
 public:
  virtual ~World() = default;
  // Lets the world run up to time t (exogenous events, overrunning actions).
  virtual void advance(double t) = 0;
  virtual WorldState observe() const = 0;
  virtual void start_action(const GroundTask& task, ActionId action, double t, double duration) = 0;
  // False when the action has not finished when the plan said it would.
  virtual bool end_action(const GroundTask& task, ActionId action, double t) = 0;
  virtual std::vector<ActionInProgress> in_progress() const = 0;
  // The actions that came to nothing, from the first-th on (a world that
  // does whatever it is told has none).
  virtual std::vector<VoidAction> void_actions_since(std::size_t /*first*/) const { return {}; }
};

}  // namespace alplan::repair
