#include "benchmarks/differential/differential.h"

#include <functional>

#include "oracle/load.h"
#include "pddl_parser/writer.h"

namespace alplan::differential {
namespace {

struct Task {
  pddl::Domain domain;
  pddl::Problem problem;
};

// Each way of dropping one part of a task: applied to a copy, it returns
// false when the part does not exist.
using Drop = std::function<bool(Task&)>;

template <typename T>
bool erase_at(std::vector<T>& v, std::size_t i) {
  if (i >= v.size()) return false;
  v.erase(v.begin() + static_cast<std::ptrdiff_t>(i));
  return true;
}

// A conjunct of a formula or effect that is a conjunction; the whole of it
// otherwise (a formula becomes (and), an effect (and)).
template <typename Node>
bool drop_part(std::optional<Node>& node, std::size_t i) {
  if (!node) return false;
  if (node->kind == Node::Kind::And) return erase_at(node->children, i);
  if (i != 0) return false;
  node.reset();
  return true;
}

std::vector<Drop> drops(const Task& t) {
  std::vector<Drop> out;
  for (std::size_t a = 0; a < t.domain.durative_actions.size(); ++a) {
    out.push_back([a](Task& x) { return erase_at(x.domain.durative_actions, a); });
    const auto& action = t.domain.durative_actions[a];
    const std::size_t conditions = action.condition ? std::max<std::size_t>(1, action.condition->children.size()) : 0;
    for (std::size_t i = 0; i < conditions; ++i) out.push_back([a, i](Task& x) { return drop_part(x.domain.durative_actions[a].condition, i); });
    const std::size_t effects = action.effect ? std::max<std::size_t>(1, action.effect->children.size()) : 0;
    for (std::size_t i = 0; i < effects; ++i) out.push_back([a, i](Task& x) { return drop_part(x.domain.durative_actions[a].effect, i); });
  }
  for (std::size_t a = 0; a < t.domain.actions.size(); ++a) {
    out.push_back([a](Task& x) { return erase_at(x.domain.actions, a); });
    const auto& action = t.domain.actions[a];
    const std::size_t conditions = action.precondition ? std::max<std::size_t>(1, action.precondition->children.size()) : 0;
    for (std::size_t i = 0; i < conditions; ++i) out.push_back([a, i](Task& x) { return drop_part(x.domain.actions[a].precondition, i); });
    const std::size_t effects = action.effect ? std::max<std::size_t>(1, action.effect->children.size()) : 0;
    for (std::size_t i = 0; i < effects; ++i) out.push_back([a, i](Task& x) { return drop_part(x.domain.actions[a].effect, i); });
  }
  for (std::size_t i = 0; i < t.problem.init.size(); ++i) out.push_back([i](Task& x) { return erase_at(x.problem.init, i); });
  for (std::size_t i = 0; i < t.problem.timed_literals.size(); ++i) out.push_back([i](Task& x) { return erase_at(x.problem.timed_literals, i); });
  const std::size_t goals = t.problem.goal ? std::max<std::size_t>(1, t.problem.goal->children.size()) : 0;
  for (std::size_t i = 0; i < goals; ++i) out.push_back([i](Task& x) { return drop_part(x.problem.goal, i); });
  const std::size_t constraints = t.problem.constraints ? std::max<std::size_t>(1, t.problem.constraints->children.size()) : 0;
  for (std::size_t i = 0; i < constraints; ++i) out.push_back([i](Task& x) { return drop_part(x.problem.constraints, i); });
  for (std::size_t i = 0; i < t.domain.derived_predicates.size(); ++i) out.push_back([i](Task& x) { return erase_at(x.domain.derived_predicates, i); });
  return out;
}

}  // namespace

Disagreement shrink(const Disagreement& found, const DifferentialOptions& options) {
  const oracle::LoadedTask loaded = oracle::load_task_text(found.domain, found.problem);
  if (!loaded.ok()) return found;
  Task best{*loaded.domain, *loaded.problem};
  Disagreement result = found;
  for (bool progress = true; progress;) {
    progress = false;
    for (const Drop& drop : drops(best)) {
      Task candidate = best;
      if (!drop(candidate)) continue;
      const std::string domain = pddl::write_domain(candidate.domain);
      const std::string problem = pddl::write_problem(candidate.problem);
      const TaskOutcome outcome = check_task(domain, problem, options);
      if (!outcome.disagreement || outcome.disagreement->kind != found.kind) continue;
      best = std::move(candidate);
      result = *outcome.disagreement;
      result.seed = found.seed;
      result.features = found.features;
      progress = true;
      break;  // the parts are numbered anew
    }
  }
  return result;
}

}  // namespace alplan::differential
