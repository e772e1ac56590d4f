#include "home/home_run.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>

#include "domains/battery_home.h"
#include "domains/emotion_goals.h"
#include "home/goal_allocation.h"
#include "home/home_perception.h"
#include "home/home_problem.h"
#include "home/object_returns.h"
#include "home/robot_dispatch.h"
#include "home/robot_faults.h"
#include "planner/formula_evaluation.h"
#include "repair/monitor.h"
#include "repair/observation.h"
#include "repair/random_events.h"
#include "repair/reformulation.h"
#include "repair/world_simulator.h"

namespace alplan::home {
namespace {

// One mission in course: its robots (one with the allocation), the goals
// it serves, its execution under the monitor, and what the home has for it
// at its next look.
struct FleetMission {
  int id = 0;
  std::vector<std::string> robots;
  std::vector<PerceivedGoal> goals;     // served by its plan
  std::vector<PerceivedGoal> incoming;  // given to it, merged at its next look
  std::vector<PerceivedGoal> merging;   // handed over, the merge's outcome not yet told
  std::vector<pddl::TimedInitialLiteral> withdrawn;  // windows settled since its last arrival
  std::set<std::string> seniors;  // whose goals it serves, for explanations
  std::string motivation;
  std::unique_ptr<repair::MonitoredExecution> execution;
  double next_look = 0.0;
  int current_plan = 0;
  bool merge_blocked = false;  // a merge found no plan: no more goals for it
  // Soft windows: planned with the windows as preferences (a goal in it is
  // served late); otherwise they are deadlines in its problem.
  bool preferred = false;
};

// Soft windows: a goal whose window no plan can meet any more.
bool late(const PerceivedGoal& g, double t) { return g.serve_late || g.window_end <= t; }

class HomeRun {
 public:
  HomeRun(const HomeSettings& settings, EventLog& log, const GoalSourceMaker& goals, RunClock& clock)
      : settings_(settings), log_(log), clock_(clock), loaded_(load_run(settings)),
        base_(calm_problem(*loaded_.home.files.problem)), perception_(goals(loaded_.map, log)),
        world_(repair::initial_world(base_), {}),
        belief_(base_, home_observation_options(settings_)),
        events_(home_event_options(settings)),
        faults_(world_, loaded_.map, settings),
        returns_(base_, settings.object_return_s),
        return_levels_(settings.battery ? domains::return_levels(base_) : std::map<std::string, double>{}),
        planner_(home_planner_options(settings)), replanner_(home_replanner_options(settings)) {
    if (settings.fleet != "allocate" && settings.fleet != "dispatch") {
      throw std::invalid_argument("--fleet " + settings.fleet + ": not allocate or dispatch");
    }
    for (const Placed& r : loaded_.map.robots) robots_.push_back(r.name);
    for (const pddl::TypedName& o : base_.objects) {
      if (!o.types.empty() && is_device_type(o.types.front())) devices_.insert(o.name);
    }
    summary_.robots = robots_.size();
    repair::StrategyOptions strategy;
    strategy.planner = replanner_;
    strategy_ = repair::make_strategy(settings.strategy, strategy);
  }

  // The home's clock: it looks every step while the robots are idle, and
  // whenever a mission asks to be looked at; at each look it senses, hears
  // the robots' fault reports, settles goals, gives new goals to robots and
  // steps every mission due.
  HomeSummary run(const std::function<void(double)>& on_time) {
    LogEvent home{"observation", 0.0, {}, {}, {}};
    home.payload = {{"what", "home"}, {"home", loaded_.map.json()}, {"settings", settings_.json()}};
    log_.write(home);
    double t = 0.0;
    while (t <= settings_.until + 1e-9) {
      if (on_time) on_time(std::min(t, settings_.until));
      if (!clock_.wait_until(t)) break;
      world_.advance(t);
      belief_.observe(world_.observe());
      for (PerceivedGoal& g : perception_->sense(t)) pending_.push_back(std::move(g));
      notice_faults(t);
      settle(t, belief_.state());
      receive(t);
      place_goals(t);
      step_missions(t);
      double next = t + settings_.step_s;
      for (const auto& m : missions_) next = std::min(next, m->next_look);
      t = std::max(next, t + 1e-6);
    }
    if (const std::optional<PerceptionScore> score = perception_->score(settings_.until)) {
      summary_.episodes = score->episodes;
      summary_.episodes_detected = score->detected;
      summary_.false_alarms = score->false_alarms;
    }
    summary_.end_time = std::min(t, settings_.until);
    for (const auto& m : missions_) summary_.in_course_at_end += m->goals.size() + m->incoming.size();
    summary_.in_course_at_end += waiting_.size() + unplannable_.size();
    report_batteries(summary_.end_time);
    return summary_;
  }

 private:
  // Each robot's battery over the run, from the world's true values: into
  // the summary and the log (one `battery` event per robot).
  void report_batteries(double t) {
    if (!settings_.battery) return;
    for (const Placed& r : loaded_.map.robots) {
      RobotBattery b;
      b.level = world_.value({"battery", r.name}).value_or(0.0);
      b.reserve = world_.value({"reserve", r.name}).value_or(0.0);
      const auto low = world_.lowest_values().find({"battery", r.name});
      b.lowest = low == world_.lowest_values().end() ? b.level : std::min(low->second, b.level);
      b.below_reserve = b.lowest < b.reserve - kNumericSlack;
      summary_.batteries[r.name] = b;
      LogEvent e{"battery", t, {}, r.name, {}};
      e.payload = {{"level", b.level}, {"lowest", b.lowest}, {"reserve", b.reserve},
                   {"below_reserve", b.below_reserve}};
      log_.write(e);
    }
  }

  double coin() { return static_cast<double>(events_random_() >> 11) * 0x1.0p-53; }

  // The facts a new goal tells the world, the belief and the home's
  // problem: the emotion read, the goal not yet reached, the window open
  // until its literal closes it.
  void tell(const PerceivedGoal& g, double t) {
    std::vector<repair::ExogenousEvent> now;
    for (const auto& [atom, value] : told_facts(g)) {
      repair::ExogenousEvent e;
      e.time = t;
      e.atom = atom;
      e.value = value;
      e.description = g.senior + ": " + atom.front() + (value ? "" : " no more");
      now.push_back(e);
      belief_.told(atom, value);
    }
    if (!settings_.soft_windows) {  // soft: the window is a preference, it closes nowhere
      repair::ExogenousEvent close;
      close.time = g.window_end;
      close.atom = {g.window, g.senior};
      close.value = false;
      close.description = g.senior + "'s window closes";
      now.push_back(close);
      // The home's own problem and belief keep the window for later missions.
      base_.timed_literals.push_back(window_close(g));
      belief_.expect(window_close(g));
    }
    world_.schedule(now);
  }

  // New goals: told, scored, and waiting for a robot.
  void receive(double t) {
    for (PerceivedGoal& g : pending_) {
      if (!g.supersedes.empty()) retire(g.senior, g.supersedes, t);
      tell(g, t);
      // A device where the senior is answers at once, in the same plan.
      if (const auto device = answering_device(g, base_, belief_.state())) {
        g.device = *device;
        ask_device_response(g);
      }
      score_meetable(g, t);
      ++summary_.goals;
      waiting_.push_back(std::move(g));
    }
    pending_.clear();
  }

  // A look at an overdue goal's senior read another emotion: the goal in
  // course gives way to the new one. A mission left with nothing to serve
  // is given up (its robot free for the new goal).
  void retire(const std::string& senior, const std::string& predicate, double t) {
    const auto retired = [&](const PerceivedGoal& g) { return g.senior == senior && g.predicate == predicate; };
    std::size_t found = std::erase_if(waiting_, retired) + std::erase_if(unplannable_, retired);
    for (auto m = missions_.begin(); m != missions_.end();) {
      FleetMission& mission = **m;
      const std::size_t here = std::erase_if(mission.goals, retired) + std::erase_if(mission.incoming, retired) +
                               std::erase_if(mission.merging, retired);
      found += here;
      if (here > 0 && mission.goals.empty() && mission.incoming.empty() && mission.merging.empty()) {
        give_up(mission, t);
        m = missions_.erase(m);
      } else {
        ++m;
      }
    }
    if (found == 0) return;
    refused_.erase(senior);
    LogEvent e{"goal_superseded", t, senior, {}, {}};
    e.payload = {{"goal", "(" + predicate + " " + senior + ")"}};
    log_.write(e);
    ++summary_.superseded;
  }

  // Robots in service: not broken down.
  std::vector<std::string> live_robots() const {
    std::vector<std::string> live;
    for (const std::string& r : robots_) {
      if (!faults_.down(r)) live.push_back(r);
    }
    return live;
  }

  // Whether one robot, idle where the home believes it stands, could meet
  // the goal's window alone: the goal's problem with that robot only and the
  // window's close, planned from now (first plan, a quarter of the node
  // limit: an unreachable window runs to it). Scoring; the run goes on as
  // if it had not been asked.
  void score_meetable(PerceivedGoal& g, double t) {
    if (!settings_.score_meetable) return;
    pddl::Problem goal_problem = base_;
    goal_problem.goal = g.goal;
    if (settings_.soft_windows) goal_problem.timed_literals.push_back(window_close(g));  // meetable: within it
    const pddl::Problem from_now = repair::reformulate(loaded_.home.domain, goal_problem, belief_.state(), {}, t, 0.0);
    PlannerOptions scoring = replanner_;  // the first plan: feasibility is the question
    scoring.node_limit = std::max<std::size_t>(1, settings_.planner_node_limit / 4);
    for (const std::string& robot : live_robots()) {
      pddl::Problem alone = with_robots_only(from_now, robots_, {robot});
      if (settings_.battery) require_return(alone, {robot}, return_levels_);
      if (repair::plan_in_process(loaded_.home.domain, alone, t, scoring).plan) {
        g.meetable_alone = true;
        ++summary_.meetable;
        return;
      }
    }
  }

  // Goals reached or out of time, as the robots believe, wherever they are.
  void settle(double t, const repair::WorldState& believed) {
    const bool served_late = settings_.soft_windows;
    for (const auto& m : missions_) {
      settle(t, believed, m->goals, served_late);
      settle(t, believed, m->incoming, served_late);
      settle(t, believed, m->merging, served_late);
    }
    settle(t, believed, waiting_, served_late);
    settle(t, believed, unplannable_, false);  // no robot has a plan: dropped when the window ends
  }

  // `served_late`: a goal whose window passes stays in course (soft windows).
  void settle(double t, const repair::WorldState& believed, std::vector<PerceivedGoal>& goals, bool served_late) {
    for (auto g = goals.begin(); g != goals.end();) {
      if (believed.holds({g->predicate, g->senior})) {
        const bool within = t <= g->window_end + 1e-6;
        LogEvent e{"comforted", t, g->senior, {}, {}};
        e.payload = {{"goal", "(" + g->predicate + " " + g->senior + ")"}, {"window_end", g->window_end},
                     {"within_window", within}};
        log_.write(e);
        ++summary_.comforted;
        summary_.within_window += within;
        summary_.meetable_within_window += within && g->meetable_alone;
        if (!within) summary_.weighted_lateness += settings_.weight_of(g->emotion) * (t - g->window_end);
        perception_->comforted(*g, t);
        collect_from(g->senior, t);
        withdraw_window(*g, t);
        refused_.erase(g->senior);
        g = goals.erase(g);
      } else if (t > g->window_end + 1e-6 && served_late) {
        if (!g->overdue) {
          LogEvent e{"window_passed", t, g->senior, {}, {}};
          e.payload = {{"goal", "(" + g->predicate + " " + g->senior + ")"}, {"window_end", g->window_end}};
          log_.write(e);
          g->overdue = true;
          perception_->overdue(*g, t);  // looked at again: the goal confirmed or superseded
          refused_.erase(g->senior);  // refused as a deadline: late, any robot may take it
        }
        ++g;
      } else if (t > g->window_end + 1e-6) {
        LogEvent e{"window_missed", t, g->senior, {}, {}};
        e.payload = {{"goal", "(" + g->predicate + " " + g->senior + ")"}, {"window_end", g->window_end}};
        log_.write(e);
        ++summary_.windows_missed;
        ++summary_.never_served;
        perception_->missed(*g, t);
        collect_from(g->senior, t);  // what was handed over in vain
        refused_.erase(g->senior);
        g = goals.erase(g);
      } else {
        ++g;
      }
    }
  }

  // A settled goal's window closes for nobody: its closing literal leaves
  // the world, the belief and the home's problem at once, and each running
  // mission's at its next arrival, so that it cannot end a later window of
  // the same senior early.
  void withdraw_window(const PerceivedGoal& g, double t) {
    if (settings_.soft_windows || g.window_end <= t) return;  // none, or closed already
    const pddl::TimedInitialLiteral close = window_close(g);
    std::erase_if(base_.timed_literals, [&](const pddl::TimedInitialLiteral& l) { return repair::same_literal(l, close); });
    belief_.withdraw(close);
    world_.cancel({g.window, g.senior}, false, g.window_end);
    for (const auto& m : missions_) m->withdrawn.push_back(close);
  }

  // Objects the mission's repairs recognised join the home's problem, so
  // that the next mission can plan with them (the shared belief knows where
  // they stand).
  void keep_recognized(const repair::ExecutionReport& report) {
    for (const repair::RepairRecord& r : report.repairs) {
      for (const repair::RecognizedObject& o : r.integrated) {
        if (repair::object_type(base_, o.name)) continue;
        pddl::TypedName object;
        object.name = o.name;
        object.types = {o.type};
        base_.objects.push_back(std::move(object));
        ++summary_.objects_recognized;
      }
    }
  }

  void collect_from(const std::string& senior, double t) {
    if (settings_.object_return_s > 0) world_.schedule(returns_.collect_from(world_.observe(), senior, t));
  }

  // Every planner call, plan found or not, by why it was made.
  void record_planning(const std::string& reason, double seconds) {
    summary_.planning_seconds.push_back(seconds);
    summary_.planning_by_reason[reason].push_back(seconds);
  }

  void log_plan(FleetMission& m, double t, const repair::ExecutingPlan& plan, const std::string& reason,
                double seconds, const pddl::Problem& problem) {
    LogEvent e{"plan", t, {}, {}, {}};
    const int id = ++plans_;
    e.payload = {{"plan_id", id}, {"reason", reason}, {"plan", repair::plan_text(plan)},
                 {"steps", steps_json(plan, loaded_.map, devices_)}, {"planning_seconds", seconds}, {"mission", m.id}};
    e.payload["supersedes"] = m.current_plan ? nlohmann::json(m.current_plan) : nlohmann::json(nullptr);
    log_.write(e);
    m.current_plan = id;
    ++summary_.plans;
    summary_.merges += reason == "merge";
    record_planning(reason, seconds);
    // The world changes against the plans the deliberation makes for new
    // goals; a repair's plan meets what the world does next, not a draw of
    // its own (else failures would beget failures without end).
    if (reason != "repair" && settings_.failure_chance > 0 && coin() < settings_.failure_chance) {
      if (faults_.draw(plan, [this] { return coin(); })) return;
      const std::vector<repair::ExogenousEvent> failure =
          events_.draw(plan, problem, &loaded_.home.ontology, ++serial_);
      world_.schedule(failure);
      if (settings_.object_return_s > 0) world_.schedule(returns_.after_failure(failure));
    }
  }

  void on_monitor_event(FleetMission& mission, const repair::MonitorEvent& m) {
    using Kind = repair::MonitorEvent::Kind;
    switch (m.kind) {
      case Kind::Plan:
        if (m.reason == "merge") mission.merging.clear();  // taken in
        log_plan(mission, m.time, *m.plan, m.reason, m.planning_seconds, mission.execution->problem());
        return;
      case Kind::ActionStart:
      case Kind::ActionEnd: {
        LogEvent e{m.kind == Kind::ActionStart ? "action_start" : "action_end", m.time, {},
                   robot_of(m.action, loaded_.map), {}};
        e.payload = {{"action", m.action}, {"plan_id", mission.current_plan}};
        if (const std::string device = device_of(m.action, devices_); !device.empty()) e.payload["device"] = device;
        if (m.kind == Kind::ActionEnd && settings_.battery && !e.robot.empty()) {
          e.payload["battery"] = world_.value({"battery", e.robot}).value_or(0.0);
        }
        log_.write(e);
        busy_time(m, e.robot);
        return;
      }
      case Kind::Failure: {
        const Violation& v = m.repair->failure;
        LogEvent e{"failure", m.time, {}, robot_of(m.action, loaded_.map), {}};
        e.payload = {{"action", v.action}, {"condition", v.condition}, {"kind", std::string(alplan::to_string(v.kind))},
                     {"foreseen", m.repair->foreseen}};
        log_.write(e);
        ++summary_.failures;
        return;
      }
      case Kind::Repair: {
        const repair::RepairRecord& r = *m.repair;
        LogEvent e{"repair", m.time, {}, {}, {}};
        e.payload = {{"strategy", r.strategy}, {"repaired", r.repaired}, {"deferred", r.deferred},
                     {"seconds", r.seconds}, {"how", r.explanation.how},
                     {"plan_id", r.repaired ? nlohmann::json(plans_ + 1) : nlohmann::json(nullptr)}};
        log_.write(e);
        if (r.repaired) ++summary_.repairs[r.strategy];
        else if (!r.deferred) ++summary_.repairs_failed;
        // A call that found no plan took its time too: latency counts it.
        if (!r.repaired && r.planner_calls > 0) record_planning("repair_failed", r.seconds);
        explain(mission.seniors, m.time, r.explanation.why, r.explanation.what, r.explanation.how);
        return;
      }
      case Kind::MergeFailed:
        record_planning("merge_failed", m.planning_seconds);
        explain(mission.seniors, m.time, "new goals arrived while a plan ran",
                "no plan serves them with the goals in force",
                m.reason + (settings_.fleet == "allocate" ? "; they go to another robot, or wait for one"
                                                           : "; they wait until the plan in force ends"));
        // The robot keeps its goals; the new ones go back to the home.
        mission.merge_blocked = true;
        for (PerceivedGoal& g : mission.merging) {
          std::erase_if(mission.goals, [&](const PerceivedGoal& h) { return h.senior == g.senior; });
          mission.seniors.erase(g.senior);
          for (const std::string& r : mission.robots) refused_[g.senior].insert(r);
          waiting_.push_back(std::move(g));
        }
        mission.merging.clear();
        return;
    }
  }

  // Each robot's time at work, from its actions' starts and ends.
  void busy_time(const repair::MonitorEvent& m, const std::string& robot) {
    if (robot.empty()) return;
    if (m.kind == repair::MonitorEvent::Kind::ActionStart) {
      started_at_[m.action] = m.time;
      return;
    }
    const auto s = started_at_.find(m.action);
    if (s == started_at_.end()) return;
    summary_.robot_busy_s[robot] += m.time - s->second;
    started_at_.erase(s);
  }

  // An explanation names the seniors of the mission it explains.
  void explain(const std::set<std::string>& about, double t, const std::string& why, const std::string& what,
               const std::string& how) {
    std::string seniors;
    for (const std::string& s : about) seniors += (seniors.empty() ? "" : ", ") + s;
    LogEvent e{"explanation", t, seniors, {}, {}};
    e.payload = {{"why", why}, {"what", what}, {"how", how}};
    log_.write(e);
  }

  // What a mission's monitor asks at every observation: the goals the home
  // gave it since, and the windows settled since.
  std::optional<repair::GoalArrival> arrivals(FleetMission& m, double t) {
    if (m.incoming.empty() || m.merge_blocked) return std::nullopt;
    repair::GoalArrival arrival;
    arrival.withdrawn = std::move(m.withdrawn);
    m.withdrawn.clear();
    for (PerceivedGoal& g : m.incoming) {
      for (const auto& fact : told_facts(g)) arrival.facts.push_back(fact);
      if (!m.preferred && !late(g, t)) arrival.timed_literals.push_back(window_close(g));
      arrival.goals.push_back(g.goal);
      arrival.motivation += (arrival.motivation.empty() ? "" : "; ") + g.motivation;
      m.seniors.insert(g.senior);
      m.goals.push_back(g);
      m.merging.push_back(std::move(g));
    }
    m.incoming.clear();
    if (m.preferred) {
      pddl::Problem preferred;
      prefer_windows(preferred, base_.metric, m.goals, t, settings_);
      arrival.preferences = repair::GoalArrival::Preferences{preferred.constraints, preferred.metric};
    }
    return arrival;
  }

  // A robot reports its own fault (robot_faults.h): its mission is given
  // up and its goals go back to the home for the robots in service.
  void notice_faults(double t) {
    for (const RobotFaults::Report& r : faults_.hear(t, belief_.state())) {
      LogEvent e{r.down ? "robot_down" : "robot_up", t, {}, r.robot, {}};
      log_.write(e);
      if (!r.down) {
        belief_.observe(world_.observe());  // where it stands again
        continue;
      }
      ++summary_.robots_down;
      for (auto m = missions_.begin(); m != missions_.end(); ++m) {
        if (std::find((*m)->robots.begin(), (*m)->robots.end(), r.robot) == (*m)->robots.end()) continue;
        explain((*m)->seniors, t, (*m)->motivation, r.robot + " broke down",
                "its mission is given up; its goals go to the robots in service");
        give_up(**m, t);
        missions_.erase(m);
        break;
      }
    }
  }

  // A mission ended or given up: the goals it did not reach go back to the
  // home, and what its robots still do goes on to its end (a robot
  // mid-move arrives).
  void give_up(FleetMission& m, double t) {
    settle(t, belief_.state());
    for (auto* list : {&m.goals, &m.incoming, &m.merging}) {
      for (PerceivedGoal& g : *list) {
        // A device answers once, where the senior was: given or no longer
        // possible, it is not asked for again.
        drop_device_response(g);
        if (std::none_of(waiting_.begin(), waiting_.end(), [&](const PerceivedGoal& w) { return w.senior == g.senior; })) {
          waiting_.push_back(std::move(g));
        }
      }
      list->clear();
    }
    for (const repair::ActionInProgress& a : m.execution->running()) world_.release(a.name);
    // A robot refused goals as a merge into this mission: idle, it may take them.
    for (auto& [senior, robots] : refused_) {
      for (const std::string& r : m.robots) robots.erase(r);
    }
  }

  // Whether a robot is free: in service, in no mission, and not finishing
  // an action a mission left.
  bool idle(const std::string& robot) const {
    if (faults_.down(robot)) return false;
    for (const auto& m : missions_) {
      if (std::find(m->robots.begin(), m->robots.end(), robot) != m->robots.end()) return false;
    }
    const std::vector<repair::ActionInProgress> running = world_.in_progress();
    return std::none_of(running.begin(), running.end(),
                        [&](const repair::ActionInProgress& a) { return robot_of(a.name, loaded_.map) == robot; });
  }

  void place_goals(double t) {
    if (waiting_.empty()) return;
    if (settings_.fleet == "dispatch") {
      place_by_dispatch(t);
    } else {
      place_by_allocation(t);
    }
  }

  // The home before issue 31: one mission at a time; goals that come while
  // it runs are merged into it, or wait for its end when a merge failed.
  void place_by_dispatch(double t) {
    if (!missions_.empty()) {
      FleetMission& m = *missions_.front();
      if (m.merge_blocked) return;
      for (PerceivedGoal& g : waiting_) m.incoming.push_back(std::move(g));
      waiting_.clear();
      return;
    }
    std::vector<std::string> free;
    for (const std::string& r : robots_) {
      if (idle(r)) free.push_back(r);
    }
    if (free.empty()) return;
    std::vector<PerceivedGoal> goals = std::move(waiting_);
    waiting_.clear();
    start_mission(free, std::move(goals), t, settings_.dispatch);
  }

  // Each waiting goal to the robot with the least weighted lateness
  // (home/goal_allocation.h): an idle robot starts a mission, a busy one
  // merges the goal into its plan at its next look.
  void place_by_allocation(double t) {
    const TravelTimes travel(believed_places(belief_.state()));
    std::vector<RobotLoad> loads;
    std::map<std::string, FleetMission*> mission_of;
    for (const auto& m : missions_) {
      if (m->merge_blocked || m->robots.size() != 1) continue;
      RobotLoad load{m->robots.front(), {}, t, false};
      const std::vector<PerceivedGoal>& served = m->incoming.empty() ? m->goals : m->incoming;
      if (!served.empty()) load.room = travel.room_of(served.back().senior).value_or("");
      for (const repair::ScheduledAction& s : m->execution->plan().steps) load.free_at = std::max(load.free_at, s.end());
      if (load.room.empty()) continue;
      loads.push_back(load);
      mission_of[load.robot] = m.get();
    }
    for (const std::string& r : robots_) {
      const std::optional<std::string> room = travel.room_of(r);
      if (idle(r) && room) loads.push_back({r, *room, t, true});
    }
    std::vector<GoalRequest> requests;
    for (const PerceivedGoal& g : waiting_) {
      GoalRequest request{g.senior, g.window_end, settings_.weight_of(g.emotion), {}};
      if (const auto refused = refused_.find(g.senior); refused != refused_.end()) {
        request.refused_by.assign(refused->second.begin(), refused->second.end());
      }
      requests.push_back(std::move(request));
    }
    AllocationOptions options;
    options.now = t;
    options.service_s = settings_.service_estimate_s;
    std::map<std::string, std::vector<PerceivedGoal>> to_idle;
    std::vector<bool> placed(waiting_.size(), false);
    for (const Assignment& a : allocate_goals(travel, loads, requests, options)) {
      placed[a.goal] = true;
      if (a.to_idle) {
        to_idle[a.robot].push_back(std::move(waiting_[a.goal]));
      } else {
        mission_of.at(a.robot)->incoming.push_back(std::move(waiting_[a.goal]));
      }
    }
    std::vector<PerceivedGoal> still;
    for (std::size_t i = 0; i < waiting_.size(); ++i) {
      if (!placed[i]) still.push_back(std::move(waiting_[i]));
    }
    waiting_ = std::move(still);
    for (auto& [robot, goals] : to_idle) start_mission({robot}, std::move(goals), t, false);
  }

  // Plans the goals with the robots from what the home believes at t and,
  // with a plan, starts their mission under the monitor; without one, see
  // unplanned(). `nearest`: the nearest of the robots per senior
  // (home/robot_dispatch.h) rather than all of them.
  void start_mission(std::vector<std::string> robots, std::vector<PerceivedGoal> goals, double t, bool nearest) {
    auto m = std::make_unique<FleetMission>();
    for (const PerceivedGoal& g : goals) {
      m->seniors.insert(g.senior);
      m->motivation += (m->motivation.empty() ? "" : "; ") + g.motivation;
    }
    // Soft windows: the windows are deadlines of the plan while a plan can
    // meet them all (the world does not close them); a goal no robot can
    // serve in time makes them preferences, weighted by urgency.
    m->preferred = settings_.soft_windows && std::any_of(goals.begin(), goals.end(), [t](const PerceivedGoal& g) {
      return late(g, t);
    });
    const pddl::Problem problem = mission_problem(robots, goals, t, nearest, m->preferred);
    const repair::PlanningOutcome planned = repair::plan_in_process(loaded_.home.domain, problem, t, planner_);
    if (!planned.plan) {
      if (!settings_.unplanned_dir.empty()) {
        write_unplanned(settings_.unplanned_dir, ++unplanned_, problem, *loaded_.home.files.domain, t);
      }
      record_planning("none", planned.seconds);
      unplanned(std::move(robots), std::move(goals), t, nearest, planned, *m);
      return;
    }
    m->id = ++missions_started_;
    m->robots = robots;
    m->goals = std::move(goals);
    log_plan(*m, t, *planned.plan, "initial", planned.seconds, problem);
    explain_devices(*m, *planned.plan, t);
    repair::Mission mission;
    mission.domain = &loaded_.home.domain;
    mission.problem = problem;
    mission.motivation = m->motivation;
    mission.robot = robots.front();
    mission.exogenous_predicates = domains::exogenous_predicates();
    mission.start_time = t;
    FleetMission* self = m.get();  // owned by missions_ for the execution's whole life
    mission.on_event = [this, self](const repair::MonitorEvent& e) { on_monitor_event(*self, e); };
    mission.arrivals = [this, self](double now, const repair::WorldState&) { return arrivals(*self, now); };
    mission.belief = &belief_;  // one belief: what one robot learns, all know
    repair::MonitorOptions options;
    options.step_size = settings_.step_s;
    // A home's plan runs long and meets many changes; a repair each is fine.
    options.max_repairs = 50;
    options.planner = replanner_;
    options.observation = home_observation_options(settings_);
    m->execution = std::make_unique<repair::MonitoredExecution>(options, mission, *planned.plan, world_, *strategy_,
                                                                &world_, &loaded_.home.ontology);
    m->next_look = std::max(t, m->execution->first_look());
    missions_.push_back(std::move(m));
  }

  // The goals' problem from what the home believes at t, with the robots
  // only (narrowed to the nearest per senior when asked); the windows as
  // deadlines, or with `preferred` as weighted preferences.
  pddl::Problem mission_problem(std::vector<std::string>& robots, const std::vector<PerceivedGoal>& goals, double t,
                                bool nearest, bool preferred) {
    pddl::Condition all;
    all.kind = pddl::Condition::Kind::And;
    for (const PerceivedGoal& g : goals) all.children.push_back(g.goal);
    pddl::Problem goal_problem = base_;
    goal_problem.goal = all;
    if (settings_.soft_windows && !preferred) {
      for (const PerceivedGoal& g : goals) goal_problem.timed_literals.push_back(window_close(g));
    }
    pddl::Problem problem = repair::reformulate(loaded_.home.domain, goal_problem, belief_.state(), {}, t, 0.0);
    if (preferred) prefer_windows(problem, base_.metric, goals, t, settings_);
    if (nearest) {
      std::vector<Call> calls;
      for (const PerceivedGoal& g : goals) calls.push_back({g.senior, g.window_end});
      std::vector<std::string> chosen = dispatch_robots(problem, robots, calls);
      if (!chosen.empty()) robots = std::move(chosen);
    }
    problem = with_robots_only(problem, robots_, robots);
    if (settings_.battery) require_return(problem, robots, return_levels_);
    return problem;
  }

  // No plan for the goals with these robots. Several goals: the most
  // urgent alone now, the others placed again at the next look (no goal is
  // dropped because another is impossible). One goal: another robot is
  // asked; when none is left, soft windows serve it late, hard ones drop it
  // until its window closes (its senior is then looked at again).
  void unplanned(std::vector<std::string> robots, std::vector<PerceivedGoal> goals, double t, bool nearest,
                 const repair::PlanningOutcome& planned, const FleetMission& m) {
    if (goals.size() > 1) {
      std::stable_sort(goals.begin(), goals.end(), [&](const PerceivedGoal& a, const PerceivedGoal& b) {
        return settings_.weight_of(a.emotion) > settings_.weight_of(b.emotion);
      });
      explain(m.seniors, t, m.motivation, "no plan reaches the goals in course together in time",
              planned.message + "; the most urgent is planned alone, the others are placed again");
      for (std::size_t i = 1; i < goals.size(); ++i) waiting_.push_back(std::move(goals[i]));
      goals.resize(1);
      start_mission(std::move(robots), std::move(goals), t, nearest);
      return;
    }
    PerceivedGoal& g = goals.front();
    if (!g.device.empty()) {  // the device's answer may be what cannot be: the robot's remedy alone
      explain(m.seniors, t, m.motivation, "no plan reaches the goal with " + g.device + "'s answer",
              planned.message + "; planned again without it");
      drop_device_response(g);
      waiting_.push_back(std::move(g));
      return;
    }
    for (const std::string& r : robots) refused_[g.senior].insert(r);
    const std::vector<std::string> live = live_robots();
    bool others = settings_.fleet == "allocate" && std::any_of(live.begin(), live.end(), [&](const std::string& r) {
      return !refused_[g.senior].count(r);
    });
    const bool made_late = !others && settings_.soft_windows && !late(g, t);
    if (made_late) {  // no robot meets the window: every robot may serve it late
      g.serve_late = true;
      refused_.erase(g.senior);
      others = true;
    }
    explain(m.seniors, t, m.motivation, "no plan reaches the goals in course in time",
            planned.message + (made_late ? "; no robot meets the window: it is planned to be served late"
                               : others  ? "; another robot is asked"
                                         : "; the seniors are looked at again when their windows close"));
    (others ? waiting_ : unplannable_).push_back(std::move(g));
  }

  // The paper's Discussion: devices answer at once beside the robots. Says
  // which, and what the robots do meanwhile.
  void explain_devices(const FleetMission& m, const repair::ExecutingPlan& plan, double t) {
    std::string devices, robots;
    for (const repair::ScheduledAction& s : plan.steps) {
      if (!device_of(s.name, devices_).empty()) devices += (devices.empty() ? "" : "; ") + s.name;
    }
    if (devices.empty()) return;
    for (const std::string& r : m.robots) robots += (robots.empty() ? "" : ", ") + r;
    explain(m.seniors, t, m.motivation, "the home's devices can answer at once, before a robot arrives",
            devices + " now, while " + robots + " brings the remedy (plan " + std::to_string(m.current_plan) + ")");
  }

  // Every mission due looks now, in the order they started; those that
  // end hand back what they did not reach.
  void step_missions(double t) {
    for (std::size_t i = 0; i < missions_.size(); ++i) {
      FleetMission& m = *missions_[i];
      if (m.next_look > t + 1e-9) continue;
      const std::optional<double> next = m.execution->step(t);
      if (next) {
        m.next_look = *next;
        continue;
      }
      const repair::ExecutionReport& report = m.execution->report();
      keep_recognized(report);
      if (!report.goal_reached) {
        explain(m.seniors, t, m.motivation, report.outcome,
                "the goals not reached are planned again while their windows last");
      }
      give_up(m, t);
    }
    std::erase_if(missions_, [](const std::unique_ptr<FleetMission>& m) { return m->execution->ended(); });
  }

  const HomeSettings& settings_;
  EventLog& log_;
  RunClock& clock_;
  LoadedRun loaded_;
  pddl::Problem base_;
  std::unique_ptr<GoalSource> perception_;
  repair::WorldSimulator world_;
  repair::Belief belief_;
  repair::RandomEventGenerator events_;
  RobotFaults faults_;
  ObjectReturns returns_;
  std::map<std::string, double> return_levels_;  // with batteries: per robot, enough to reach a dock
  std::mt19937_64 events_random_{settings_.seed * 104729 + 3};
  PlannerOptions planner_, replanner_;
  std::unique_ptr<repair::RepairStrategy> strategy_;
  std::vector<std::string> robots_;
  std::set<std::string> devices_;  // speakers, lamps, TVs: their actions need no robot
  std::vector<PerceivedGoal> pending_;  // sensed, not yet told
  std::vector<PerceivedGoal> waiting_;  // told, no robot yet
  std::vector<PerceivedGoal> unplannable_;  // no plan found: they wait for their windows to close
  std::vector<std::unique_ptr<FleetMission>> missions_;
  std::map<std::string, std::set<std::string>> refused_;  // senior -> robots whose merge found no plan
  std::map<std::string, double> started_at_;              // actions under way, for busy times
  int plans_ = 0, serial_ = 0, unplanned_ = 0, missions_started_ = 0;
  HomeSummary summary_;
};

}  // namespace

HomeSummary run_home(const HomeSettings& settings, EventLog& log, const std::function<void(double)>& on_time) {
  SimulatedClock clock;
  const GoalSourceMaker seniors = [&settings](const HomeMap& map, EventLog& to) {
    return std::make_unique<HomePerception>(map, settings, to);
  };
  return run_home(settings, log, seniors, clock, on_time);
}

HomeSummary run_home(const HomeSettings& settings, EventLog& log, const GoalSourceMaker& goals, RunClock& clock,
                     const std::function<void(double)>& on_time) {
  HomeRun run(settings, log, goals, clock);
  return run.run(on_time);
}

}  // namespace alplan::home
