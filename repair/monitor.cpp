#include "repair/monitor.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "pddl_parser/writer.h"
#include "repair/timeline.h"

namespace alplan::repair {
namespace {

std::string time_text(double t) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", t);
  return buffer;
}

std::string location_of(const WorldState& world, const std::string& object) {
  for (const AtomKey& a : world.atoms) {
    if (a.size() == 3 && a[0] == "be" && a[1] == object) return a[2];
  }
  return {};
}

// Where each step of the executing plan stands.
struct Progress {
  std::vector<bool> started, ended;
  explicit Progress(std::size_t n) : started(n, false), ended(n, false) {}
};

// An action a replaced plan had started: the new plan takes it as given
// (it was compiled into the problem), but its end must still be dispatched.
struct CommittedEnd {
  std::shared_ptr<const GroundTask> task;
  ActionId action = 0;
  double end = 0.0;
};

// The next time to look: the next happening after t, or t + step.
double next_observation(const Timeline& timeline, const std::vector<CommittedEnd>& committed, double t,
                        double step) {
  double next = t + step;
  for (double h : timeline.happening_times()) {
    if (h > t + 1e-9) {
      next = std::min(next, h);
      break;
    }
  }
  for (const CommittedEnd& c : committed) {
    if (c.end > t + 1e-9) next = std::min(next, c.end);
  }
  return next;
}

}  // namespace

std::size_t plan_distance(const ExecutingPlan& before, const ExecutingPlan& after, double from) {
  std::map<std::string, int> count;
  for (const ScheduledAction& s : before.steps) {
    if (s.start + 1e-9 >= from) ++count[s.name];
  }
  for (const ScheduledAction& s : after.steps) {
    if (s.start + 1e-9 >= from) --count[s.name];
  }
  std::size_t distance = 0;
  for (const auto& [name, c] : count) distance += static_cast<std::size_t>(std::abs(c));
  return distance;
}

nlohmann::json ExecutionReport::json() const {
  nlohmann::json repairs_json = nlohmann::json::array();
  for (const RepairRecord& r : repairs) {
    repairs_json.push_back({{"time", r.failure.time},
                            {"kind", to_string(r.failure.kind)},
                            {"action", r.failure.action},
                            {"condition", r.failure.condition},
                            {"foreseen", r.foreseen},
                            {"strategy", r.strategy},
                            {"repaired", r.repaired},
                            {"seconds", r.seconds},
                            {"planner_calls", r.planner_calls},
                            {"plan_distance", r.plan_distance},
                            {"plan", r.plan_text},
                            {"explanation", r.explanation.json()}});
  }
  return {{"initial_plan", initial_plan_text}, {"repairs", repairs_json}, {"goal_reached", goal_reached},
          {"end_time", end_time}, {"outcome", outcome}, {"events", events}};
}

ExecutionReport Monitor::run(const Mission& mission, ExecutingPlan plan, World& world, RepairStrategy& strategy,
                             ObjectRecognizer* recognizer, const TypeOntology* ontology) const {
  ExecutionReport report;
  report.initial_plan_text = plan_text(plan);
  plan = with_all_conditions(plan);
  pddl::Problem problem = mission.problem;
  const std::string goal = problem.goal ? pddl::write_condition(*problem.goal) : "(and)";
  auto timeline = std::make_unique<Timeline>(plan);
  auto mapping = std::make_unique<StateMapping>(*plan.task);
  Progress progress(plan.steps.size());
  std::vector<CommittedEnd> committed;
  const double tolerance = plan.epsilon / 10.0;
  double t = plan.steps.empty() ? 0.0 : std::min(0.0, plan.steps.front().start);
  for (int guard = 0; guard < 1000000; ++guard) {
    world.advance(t);
    const WorldState observed = world.observe();
    const ExplicitState state = mapping->to_explicit(observed);
    const bool all_dispatched =
        committed.empty() && std::all_of(progress.ended.begin(), progress.ended.end(), [](bool e) { return e; });
    std::optional<Violation> failure = timeline->check_due(t, state);
    bool foreseen = false;
    if (!failure && options_.lookahead) {
      failure = timeline->check_ahead(t, state);
      foreseen = failure.has_value();
    }
    if (!failure && all_dispatched && t + tolerance >= timeline->end_time()) {
      failure = timeline->check_goal(t, state);
      if (!failure) {
        report.goal_reached = true;
        report.end_time = t;
        report.outcome = "the goal " + goal + " holds at " + time_text(t);
        report.events.push_back(time_text(t) + ": goal reached");
        return report;
      }
    }
    if (failure) {
      report.events.push_back(time_text(t) + ": failure: " + describe_failure(*failure, foreseen));
      if (static_cast<int>(report.repairs.size()) >= options_.max_repairs) {
        report.end_time = t;
        report.outcome = "gave up after " + std::to_string(report.repairs.size()) + " repairs: " +
                         describe_failure(*failure, foreseen);
        return report;
      }
      RepairRequest request;
      request.domain = mission.domain;
      request.problem = &problem;
      request.plan = &plan;
      request.failure = &*failure;
      request.observed = observed;
      request.in_progress = world.in_progress();
      request.now = t;
      request.robot_location = location_of(observed, mission.robot);
      request.recognizer = recognizer;
      request.ontology = ontology;
      RepairResult result = strategy.repair(request);
      RepairRecord record;
      record.failure = *failure;
      record.foreseen = foreseen;
      record.strategy = strategy.name();
      record.repaired = result.repaired;
      record.seconds = result.seconds;
      record.planner_calls = result.planner_calls;
      record.integrated = result.integrated;
      record.explanation.why = mission.motivation + "; the plan's goal was " + goal;
      record.explanation.what = describe_failure(*failure, foreseen);
      record.explanation.how = result.how;
      if (!result.repaired) {
        report.repairs.push_back(record);
        report.end_time = t;
        report.outcome = "no repair: " + result.how;
        report.events.push_back(time_text(t) + ": " + strategy.name() + " could not repair: " + result.how);
        return report;
      }
      record.plan_text = plan_text(*result.plan);
      record.plan_distance = plan_distance(plan, *result.plan, t);
      report.repairs.push_back(record);
      report.events.push_back(time_text(t) + ": repaired by " + strategy.name() + ": " + result.how);
      for (std::size_t s = 0; s < plan.steps.size(); ++s) {
        if (progress.started[s] && !progress.ended[s]) committed.push_back({plan.task, plan.steps[s].action, plan.steps[s].end()});
      }
      problem = std::move(result.problem);
      plan = with_all_conditions(*result.plan);
      timeline = std::make_unique<Timeline>(plan);
      mapping = std::make_unique<StateMapping>(*plan.task);
      progress = Progress(plan.steps.size());
      continue;  // look again at the same time, with the new plan
    }
    // Dispatch what happens now: ends first, then starts.
    for (auto c = committed.begin(); c != committed.end();) {
      if (c->end > t + tolerance) {
        ++c;
        continue;
      }
      world.end_action(*c->task, c->action, t);
      c = committed.erase(c);
    }
    for (std::size_t s = 0; s < plan.steps.size(); ++s) {
      const ScheduledAction& a = plan.steps[s];
      const bool durative = plan.task->actions[a.action].durative;
      if (durative && progress.started[s] && !progress.ended[s] && std::abs(a.end() - t) <= tolerance) {
        if (!world.end_action(*plan.task, a.action, t)) {
          report.events.push_back(time_text(t) + ": " + a.name + " has not finished as planned");
        }
        progress.ended[s] = true;
      }
    }
    for (std::size_t s = 0; s < plan.steps.size(); ++s) {
      const ScheduledAction& a = plan.steps[s];
      if (progress.started[s] || std::abs(a.start - t) > tolerance) continue;
      world.start_action(*plan.task, a.action, t, a.duration);
      progress.started[s] = true;
      if (!plan.task->actions[a.action].durative) progress.ended[s] = true;
      report.events.push_back(time_text(t) + ": start " + a.name);
    }
    const bool finished =
        committed.empty() && std::all_of(progress.ended.begin(), progress.ended.end(), [](bool e) { return e; });
    // Once the last end is dispatched, judge the goal at once, not a step later.
    if (!finished || t + tolerance < timeline->end_time()) t = next_observation(*timeline, committed, t, options_.step_size);
  }
  report.outcome = "the monitor stopped: too many observations";
  return report;
}

}  // namespace alplan::repair
