// Batteries for a home of the assisted-living domain (issue 15): the
// functions and the dock that domains/assisted_living/battery/domain.pddl
// needs, added to a home's problem. `alplan home --battery` runs the paper's
// home, a home file or a generated home through here, so one place decides
// where the dock goes and what a battery starts with.
#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "pddl_parser/ast.h"

namespace alplan::domains {

// Per robot, in percent of a full battery and per second. A round trip from
// a bedroom to the kitchen of the paper's home (280 s of moving) costs 14 at
// 0.05 a second, so a full robot serves five or so before it must recharge;
// a charge of 0.5 a second fills the 80 above the reserve in 160 s.
struct BatteryOptions {
  double capacity = 100.0;
  double reserve = 20.0;
  double drain_rate = 0.05;
  double charge_rate = 0.5;
  double initial = 100.0;

  nlohmann::json json() const;
  // Throws std::invalid_argument naming a missing or wrong field.
  static BatteryOptions from_json(const nlohmann::json& json);
  // Throws std::invalid_argument naming a value that makes no battery
  // (rates not positive, reserve above capacity, a start outside 0..capacity).
  void check() const;
};

// The location with the least total moving time to every other location
// along the problem's paths (shortest ways; ties: the first by name): where
// one dock serves the whole home best. Empty when there are no locations.
std::string central_location(const pddl::Problem& problem);

// Adds to `problem` what it lacks of the battery domain: for each robot
// (objects of type robot) the battery, capacity, reserve, drain and charge
// rates from `options` (values the problem already gives stand), and, when
// the problem has no (dock ...), one dock at the central location.
void add_batteries(pddl::Problem& problem, const BatteryOptions& options);

// Per robot, the level that takes it from the location farthest from a
// dock to the nearest dock without going below its reserve: reserve +
// drain rate x that moving time (paths are walked both ways in the homes).
// A robot ending every mission at or above it can always get to a dock;
// the domain's reserve alone keeps plans safe, not robots able to recharge.
// Throws std::invalid_argument when a robot lacks a reserve, drain rate or
// capacity, or a full battery is not enough.
std::map<std::string, double> return_levels(const pddl::Problem& problem);

}  // namespace alplan::domains
