#include "report/plan_history.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace alplan::report {
namespace {

using nlohmann::json;

// Half a millisecond: a plan made at t and its first step at t print alike.
constexpr double kEpsilon = 5e-4;

std::string step_robot(const json& step, const std::string& action) {
  const std::string robot = text_field(step, "robot");
  if (!robot.empty()) return robot;
  // A device's action (a speaker playing) has its own row.
  const std::string device = text_field(step, "device");
  if (!device.empty()) return device;
  // The domain's actions name their robot first: (move robot1 a b).
  const std::vector<std::string> terms = action_terms(action);
  return terms.size() > 1 ? terms[1] : "";
}

void add_plan(const Event& e, PlanHistory& history) {
  PlanRecord plan;
  plan.plan_id = *optional_int(e.fields, "plan_id");
  plan.time = e.time;
  plan.reason = text_field(e.fields, "reason");
  plan.supersedes = optional_int(e.fields, "supersedes");
  plan.planning_seconds = number_field(e.fields, "planning_seconds");
  history.plans.push_back(plan);

  std::vector<PlanStep> steps;
  const json& list = e.fields.contains("steps") ? e.fields["steps"] : json();
  if (!list.is_array()) return;
  for (const json& s : list) {
    const std::string action = text_field(s, "action");
    if (action.empty()) continue;
    PlanStep step;
    step.plan_id = plan.plan_id;
    step.action = action;
    step.robot = step_robot(s, action);
    step.start = number_field(s, "start");
    step.duration = std::max(0.0, number_field(s, "duration"));
    steps.push_back(step);
  }
  double first = std::numeric_limits<double>::infinity();
  for (const PlanStep& s : steps) first = std::min(first, s.start);
  const double shift = first < plan.time - kEpsilon ? plan.time : 0;
  for (PlanStep& s : steps) {
    s.start += shift;
    history.steps.push_back(s);
  }
}

// The plan an action_start without a plan_id belongs to: the latest plan
// made by then with a step of that action.
std::optional<int> guess_plan(const PlanHistory& h, const std::string& action, double time) {
  std::optional<int> found;
  for (const PlanRecord& p : h.plans) {
    if (p.time > time + kEpsilon) continue;
    const bool has = std::any_of(h.steps.begin(), h.steps.end(),
                                 [&](const PlanStep& s) { return s.plan_id == p.plan_id && s.action == action; });
    if (has) found = p.plan_id;
  }
  return found;
}

// The earliest step of the plan with that action still waiting for the
// event: a plan may move a robot along the same corridor twice.
PlanStep* waiting_step(PlanHistory& h, int plan_id, const std::string& action, bool for_end) {
  PlanStep* best = nullptr;
  for (PlanStep& s : h.steps) {
    if (s.plan_id != plan_id || s.action != action) continue;
    const bool waiting = for_end ? (s.started_at && !s.ended_at) : !s.started_at;
    if (waiting && (!best || s.start < best->start)) best = &s;
  }
  return best;
}

void match_execution(const EventLog& log, PlanHistory& h) {
  for (const Event& e : log.events) {
    if (e.type != "action_start" && e.type != "action_end") continue;
    const std::string action = text_field(e.fields, "action");
    const std::optional<int> plan = optional_int(e.fields, "plan_id") ? optional_int(e.fields, "plan_id")
                                                                      : guess_plan(h, action, e.time);
    if (!plan) continue;
    PlanStep* step = waiting_step(h, *plan, action, e.type == "action_end");
    if (!step) continue;
    (e.type == "action_start" ? step->started_at : step->ended_at) = e.time;
  }
}

}  // namespace

const char* to_string(StepStatus s) {
  switch (s) {
    case StepStatus::Ran: return "ran";
    case StepStatus::NeverRan: return "never ran (superseded)";
    case StepStatus::NotStarted: return "not started";
  }
  return "";
}

std::vector<std::string> action_terms(const std::string& action) {
  const auto open = action.find('(');
  const auto close = action.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open) return {};
  std::istringstream in(action.substr(open + 1, close - open - 1));
  std::vector<std::string> terms;
  for (std::string t; in >> t;) terms.push_back(t);
  return terms;
}

PlanHistory plan_history(const EventLog& log) {
  PlanHistory h;
  for (const Event& e : log.events) {
    if (e.type == "plan") add_plan(e, h);
  }
  for (const PlanRecord& later : h.plans) {
    if (!later.supersedes) continue;
    for (PlanRecord& p : h.plans) {
      if (p.plan_id == *later.supersedes && !p.superseded_at) p.superseded_at = later.time;
    }
  }
  match_execution(log, h);
  for (PlanStep& s : h.steps) {
    const auto plan = std::find_if(h.plans.begin(), h.plans.end(), [&](const PlanRecord& p) { return p.plan_id == s.plan_id; });
    if (s.started_at) {
      s.status = StepStatus::Ran;
    } else if (plan != h.plans.end() && plan->superseded_at) {
      s.status = StepStatus::NeverRan;
    } else {
      s.status = StepStatus::NotStarted;
    }
  }
  return h;
}

std::map<std::string, std::vector<Move>> robot_routes(const EventLog& log) {
  std::map<std::string, std::vector<Move>> routes;
  for (const Event& e : log.events) {
    if (e.type != "action_start") continue;
    const std::vector<std::string> terms = action_terms(text_field(e.fields, "action"));
    if (terms.size() < 4 || terms[0] != "move") continue;
    const std::string robot = e.robot.empty() ? terms[1] : e.robot;
    routes[robot].push_back({e.time, robot, terms[2], terms[3]});
  }
  for (auto& [robot, moves] : routes) {
    std::stable_sort(moves.begin(), moves.end(), [](const Move& a, const Move& b) { return a.time < b.time; });
  }
  return routes;
}

}  // namespace alplan::report
