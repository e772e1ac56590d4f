#include "planner/ground_trajectory.h"

#include <algorithm>
#include <map>

namespace alplan {
namespace {

void bind_from(const NormalizedTask& task, const std::vector<QuantifiedVariable>& variables, std::size_t index,
               std::vector<ObjectId>& binding, const std::function<void()>& visit) {
  if (index == variables.size()) {
    visit();
    return;
  }
  const QuantifiedVariable& v = variables[index];
  if (binding.size() <= v.slot) binding.resize(v.slot + 1, kNoId);
  for (ObjectId o : task.types[v.type].objects) {
    binding[v.slot] = o;
    bind_from(task, variables, index + 1, binding, visit);
  }
}

std::string with_binding(const NormalizedTask& task, const std::vector<QuantifiedVariable>& variables,
                         const std::vector<ObjectId>& binding) {
  std::string s;
  for (const QuantifiedVariable& v : variables) {
    s += (s.empty() ? " with " : ", ") + v.name + " = " + task.objects[binding[v.slot]];
  }
  return s;
}

}  // namespace

void for_each_binding(const NormalizedTask& task, const std::vector<QuantifiedVariable>& variables,
                      std::vector<ObjectId>& binding, const std::function<void()>& visit) {
  bind_from(task, variables, 0, binding, visit);
}

std::vector<GroundPreference> ground_preferences(const std::vector<PreferenceCondition>& preferences,
                                                 std::vector<ObjectId> binding, Instantiator& instantiate) {
  std::vector<GroundPreference> result;
  for (const PreferenceCondition& p : preferences) {
    for_each_binding(instantiate.task(), p.forall, binding, [&] {
      std::vector<ObjectId> scratch = binding;
      result.push_back({p.preference, instantiate.preference_condition(p.condition, scratch), p.time});
    });
  }
  return result;
}

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
