#include "planner/ground_trajectory.h"

#include <algorithm>
#include <map>

namespace alplan {
namespace {

std::string with_binding(const NormalizedTask& task, const std::vector<QuantifiedVariable>& variables,
                         const std::vector<ObjectId>& binding) {
  std::string s;
  for (const QuantifiedVariable& v : variables) {
    s += (s.empty() ? " with " : ", ") + v.name + " = " + task.objects[binding[v.slot]];
  }
  return s;
}

}  // namespace

GroundTrajectory ground_trajectory(const NormalizedTask& task, Instantiator& instantiate) {
  GroundTrajectory result;
  const TrajectoryConstraints& lifted = task.pddl3;
  std::vector<ObjectId> goal_binding(task.goal_variable_slots, kNoId);
  result.goal_preferences = ground_preferences(lifted.goal_preferences, goal_binding, instantiate);
  // Monitors by (group, binding of the variables outside the preference).
  std::map<std::pair<std::uint32_t, std::vector<ObjectId>>, std::uint32_t> monitors;
  for (const LiftedConstraint& k : lifted.constraints) {
    std::vector<ObjectId> binding(k.variable_slots, kNoId);
    for_each_binding(task, k.forall, binding, [&] {
      std::vector<ObjectId> scratch = binding;
      GroundConstraint g;
      g.op = k.op;
      g.requirement = instantiate.condition(k.requirement, scratch);
      g.trigger = instantiate.condition(k.trigger, scratch);
      g.deadline = k.deadline;
      g.from = k.from;
      g.preference = k.preference;
      std::vector<ObjectId> outside;
      for (std::size_t i = 0; i < k.separate && i < k.forall.size(); ++i) outside.push_back(binding[k.forall[i].slot]);
      auto [it, inserted] = monitors.try_emplace({k.monitor_group, std::move(outside)}, result.monitors);
      if (inserted) ++result.monitors;
      g.monitor = it->second;
      g.text = k.text + with_binding(task, k.forall, binding) + " (" + k.where + ")";
      result.constraints.push_back(std::move(g));
    });
  }
  return result;
}

}  // namespace alplan
