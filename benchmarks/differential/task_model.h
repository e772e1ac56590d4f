// The generator's picture of a task before it is written as PDDL
// (task_generator.h draws it, task_writer.cpp writes it). Formulas and
// effects are kept as PDDL text: the model is only ever written.
#pragma once

#include <string>
#include <vector>

namespace alplan::differential {

struct ActionModel {
  std::string name;
  bool durative = true;
  bool parameter = false;  // one parameter ?x - obj
  std::string duration = "(= ?duration 1)";
  // Untimed formulas and effects, by when they apply (an instantaneous
  // action uses at_start and start_effects).
  std::vector<std::string> at_start, over_all, at_end;
  std::vector<std::string> start_effects, end_effects;
  // Already complete conjuncts (timed where durative): conditional effects
  // decided at the start, preferences.
  std::vector<std::string> conditions, effects;
};

struct TaskModel {
  std::string name;
  int facts = 3;     // nullary f0 ..
  int unary = 0;     // unary g0 .. over obj
  int objects = 2;   // o1 ..
  int fluents = 0;   // x0 ..
  std::vector<std::string> derived;  // complete (:derived ...) forms
  std::vector<ActionModel> actions;
  std::vector<std::string> init;     // atoms, (= (x) v) and (at t ...) forms
  std::vector<std::string> goal;
  std::vector<std::string> constraints;
  std::vector<std::string> metric_terms;  // summed with (total-time)
  std::vector<std::string> requirements;
  std::vector<std::string> features;
};

std::string write_domain(const TaskModel& model);
std::string write_problem(const TaskModel& model);

}  // namespace alplan::differential
