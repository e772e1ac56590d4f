#include "home/home_run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "domains/battery_home.h"
#include "domains/emotion_goals.h"
#include "domains/home_generator.h"
#include "domains/mission_run.h"
#include "home/home_perception.h"
#include "home/object_returns.h"
#include "home/robot_dispatch.h"
#include "pddl_parser/writer.h"
#include "planner/evaluation.h"
#include "repair/monitor.h"
#include "repair/observation.h"
#include "repair/random_events.h"
#include "repair/reformulation.h"
#include "repair/world_simulator.h"

namespace alplan::home {
namespace {

struct LoadedRun {
  domains::LoadedHome home;
  HomeMap map;
};

// The domain the run plans with: the paper's, or its battery variant.
std::string domain_file(const HomeSettings& s) {
  return s.domains_dir + (s.battery ? "/battery/domain.pddl" : "/domain.pddl");
}

// With batteries, the home's problem gains what it lacks of them.
domains::LoadedHome with_batteries(domains::LoadedHome home, const HomeSettings& s) {
  if (!s.battery) return home;
  pddl::Problem problem = *home.files.problem;
  domains::add_batteries(problem, s.battery_options);
  home.files.problem = std::make_shared<const pddl::Problem>(std::move(problem));
  return home;
}

domains::LoadedHome load_files(const HomeSettings& s) {
  const std::string ontology = s.domains_dir + "/types.ttl";
  if (s.generate_seniors > 0) {
    domains::HomeOptions options;
    options.seniors = s.generate_seniors;
    options.robots = s.generate_robots;
    if (s.generate_rooms > 0) options.rooms = s.generate_rooms;
    if (s.generate_objects > 0) options.objects = s.generate_objects;
    options.stressed = 1;  // the generator wants one; calm_problem takes every emotion away
    options.seed = s.seed;
    const domains::GeneratedHome generated = domains::generate_home(options);
    domains::LoadedHome paper = domains::load_home_files(domain_file(s), s.domains_dir + "/home.pddl", ontology);
    domains::LoadedFiles files = domains::load_pddl_text(pddl::write_domain(*paper.files.domain), "domain.pddl",
                                                         generated.problem, "generated-home.pddl");
    return {std::move(files), std::move(paper.ontology), std::move(paper.domain)};
  }
  const std::string file = s.home_file.empty() ? s.domains_dir + "/home.pddl" : s.home_file;
  return domains::load_home_files(domain_file(s), file, ontology);
}

LoadedRun load(const HomeSettings& s) {
  domains::LoadedHome home = with_batteries(load_files(s), s);
  HomeMap map = read_home_map(*home.files.problem);
  return {std::move(home), std::move(map)};
}

// The home's problem with nothing to do: no emotion, window or goal yet.
pddl::Problem calm_problem(const pddl::Problem& problem) {
  pddl::Problem out = problem;
  const auto about_moods = [](const pddl::Atom& a) {
    for (const char* p : {"terrified", "sad", "bored", "hydration_time", "comfort_time", "soothed", "cheerful",
                          "entertained"}) {
      if (a.name == p) return true;
    }
    return false;
  };
  out.init.erase(std::remove_if(out.init.begin(), out.init.end(), about_moods), out.init.end());
  out.timed_literals.clear();
  pddl::Condition none;
  none.kind = pddl::Condition::Kind::And;
  out.goal = none;
  return out;
}

std::string robot_of(const std::string& action, const HomeMap& map) {
  std::istringstream words(action.size() > 2 ? action.substr(1, action.size() - 2) : action);
  for (std::string w; words >> w;) {
    if (map.has_robot(w)) return w;
  }
  return {};
}

nlohmann::json steps_json(const repair::ExecutingPlan& plan, const HomeMap& map) {
  nlohmann::json steps = nlohmann::json::array();
  for (const repair::ScheduledAction& s : plan.steps) {
    steps.push_back({{"start", s.start}, {"duration", s.duration}, {"action", s.name}, {"robot", robot_of(s.name, map)}});
  }
  return steps;
}

// Thrown through the monitor when the clock stops the run mid-plan (the
// monitor has no other way out); caught by HomeRun::run.
struct ClockStopped {};

class HomeRun {
 public:
  HomeRun(const HomeSettings& settings, EventLog& log, const GoalSourceMaker& goals, RunClock& clock)
      : settings_(settings), log_(log), clock_(clock), loaded_(load(settings)),
        base_(calm_problem(*loaded_.home.files.problem)), perception_(goals(loaded_.map, log)),
        world_(repair::initial_world(base_), {}),
        belief_(base_, observation_options()),
        events_(event_options()),
        returns_(base_, settings.object_return_s),
        return_levels_(settings.battery ? domains::return_levels(base_) : std::map<std::string, double>{}) {
    // One evaluation per expansion, not one per child: the anytime
    // weights cost a sixth of the time with the same outcomes (1 h of the
    // large home, home/README.md). EHC's own budget counts expansions; EHC
    // stores about two nodes per expansion on the home's relevant actions
    // (~16 children each), so a fifth of the node limit leaves the fallback
    // searches room.
    SearchShorthands search;
    search.knobs.deferred = true;
    search.knobs.ehc_expansions = std::min<std::uint64_t>(search.knobs.ehc_expansions, settings.planner_node_limit / 5);
    search.anytime = settings.planner_expansions > 0;
    search.anytime_min_weight = 3.0;
    search.anytime_expansions = settings.planner_expansions;
    planner_.search = configuration_from(search);
    planner_.time_limit = settings.planning_time;
    planner_.node_limit = settings.planner_node_limit;
    planner_.epsilon = 0.002;
    // In real time the world goes on while the planner thinks: no step
    // starts before the planning budget has passed.
    planner_.reserve_planning_time = settings.live;
    // Repairs and merges answer a world that has changed under a running
    // plan: their first plan goes out, improved only as far as this allows.
    replanner_ = planner_;
    search.anytime = settings.replan_expansions > 0;
    search.anytime_expansions = settings.replan_expansions;
    replanner_.search = configuration_from(search);
    repair::StrategyOptions strategy;
    strategy.planner = replanner_;
    strategy_ = repair::make_strategy(settings.strategy, strategy);
  }

  HomeSummary run(const std::function<void(double)>& on_time) {
    LogEvent home{"observation", 0.0, {}, {}, {}};
    home.payload = {{"what", "home"}, {"home", loaded_.map.json()}, {"settings", settings_.json()}};
    log_.write(home);
    double t = 0.0;
    for (; t <= settings_.until + 1e-9;) {
      if (on_time) on_time(std::min(t, settings_.until));
      if (!clock_.wait_until(t)) break;
      world_.advance(t);
      belief_.observe(world_.observe());
      for (PerceivedGoal& g : perception_->sense(t)) pending_.push_back(std::move(g));
      settle(t, belief_.state());
      if (!pending_.empty() || replan_) {
        try {
          t = std::max(t, mission(t));
        } catch (const ClockStopped&) {
          break;
        }
        continue;
      }
      t += settings_.step_s;
    }
    if (const std::optional<PerceptionScore> score = perception_->score(settings_.until)) {
      summary_.episodes = score->episodes;
      summary_.episodes_detected = score->detected;
      summary_.false_alarms = score->false_alarms;
    }
    summary_.end_time = std::min(t, settings_.until);
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

  repair::ObservationOptions observation_options() const {
    repair::ObservationOptions o;
    const auto model = repair::observation_model(settings_.observe);
    if (!model) throw std::invalid_argument("--observe " + settings_.observe + ": not full, iot or camera");
    o.model = *model;
    return o;
  }

  repair::RandomEventOptions event_options() const {
    repair::RandomEventOptions o;
    o.seed = settings_.seed * 7919 + 17;
    o.kinds.clear();
    for (const std::string& k : settings_.failure_kinds) {
      const auto kind = repair::random_event_kind(k);
      if (!kind) throw std::invalid_argument("failure kind " + k + ": not one of the repair study's kinds");
      o.kinds.push_back(*kind);
    }
    return o;
  }

  double coin() { return static_cast<double>(events_random_() >> 11) * 0x1.0p-53; }

  // The facts a new goal tells the world and the robot: the emotion read,
  // the goal not yet reached, the window open until its literal closes it.
  void tell(const PerceivedGoal& g, double t, repair::GoalArrival& arrival) {
    std::vector<repair::ExogenousEvent> now;
    const auto set = [&](const std::string& predicate, bool value) {
      repair::ExogenousEvent e;
      e.time = t;
      e.atom = {predicate, g.senior};
      e.value = value;
      e.description = g.senior + ": " + predicate + (value ? "" : " no more");
      now.push_back(e);
      arrival.facts.push_back({e.atom, value});
      belief_.told(e.atom, value);
    };
    for (const char* e : {"terrified", "sad", "bored"}) set(e, g.emotion == e);
    for (const char* p : {"soothed", "cheerful", "entertained"}) set(p, false);
    set(g.window, true);
    repair::ExogenousEvent close;
    close.time = g.window_end;
    close.atom = {g.window, g.senior};
    close.value = false;
    close.description = g.senior + "'s window closes";
    now.push_back(close);
    world_.schedule(now);
    pddl::TimedInitialLiteral til;
    til.time = g.window_end;
    til.positive = false;
    til.atom = domains::senior_atom(g.window, g.senior);
    arrival.timed_literals.push_back(til);
    // The home's own problem and belief keep the window for later missions
    // (a goal merged into a running plan is planned again after it).
    base_.timed_literals.push_back(til);
    belief_.expect(til);
    arrival.goals.push_back(g.goal);
    arrival.motivation += (arrival.motivation.empty() ? "" : "; ") + g.motivation;
  }

  repair::GoalArrival take_pending(double t) {
    repair::GoalArrival arrival;
    arrival.withdrawn = std::move(withdrawn_);
    withdrawn_.clear();
    for (PerceivedGoal& g : pending_) {
      mission_seniors_.insert(g.senior);
      tell(g, t, arrival);
      score_meetable(g, t);
      active_.push_back(std::move(g));
      ++summary_.goals;
    }
    pending_.clear();
    return arrival;
  }

  // Whether one robot, idle where the home believes it stands, could meet
  // the goal's window alone: the goal's problem with that robot only and the
  // window's close, planned from now (first plan, a quarter of the node
  // limit: an unreachable window runs to it). Scoring; the run goes on as
  // if it had not been asked.
  void score_meetable(PerceivedGoal& g, double t) {
    if (!settings_.score_meetable) return;
    std::vector<std::string> all;
    for (const Placed& r : loaded_.map.robots) all.push_back(r.name);
    pddl::Problem goal_problem = base_;
    goal_problem.goal = g.goal;
    const pddl::Problem from_now = repair::reformulate(loaded_.home.domain, goal_problem, belief_.state(), {}, t, 0.0);
    PlannerOptions scoring = replanner_;  // the first plan: feasibility is the question
    scoring.node_limit = std::max<std::size_t>(1, settings_.planner_node_limit / 4);
    for (const std::string& robot : all) {
      pddl::Problem alone = with_robots_only(from_now, all, {robot});
      require_return(alone, {robot});
      if (repair::plan_in_process(loaded_.home.domain, alone, t, scoring).plan) {
        g.meetable_alone = true;
        ++summary_.meetable;
        return;
      }
    }
  }

  // Goals reached or out of time, as the robot believes.
  void settle(double t, const repair::WorldState& believed) {
    settle(t, believed, active_);
    settle(t, believed, unplannable_);
  }

  void settle(double t, const repair::WorldState& believed, std::vector<PerceivedGoal>& goals) {
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
        perception_->comforted(*g, t);
        collect_from(g->senior, t);
        withdraw_window(*g, t);
        g = goals.erase(g);
      } else if (t > g->window_end + 1e-6) {
        LogEvent e{"window_missed", t, g->senior, {}, {}};
        e.payload = {{"goal", "(" + g->predicate + " " + g->senior + ")"}, {"window_end", g->window_end}};
        log_.write(e);
        ++summary_.windows_missed;
        perception_->missed(*g, t);
        collect_from(g->senior, t);  // what was handed over in vain
        g = goals.erase(g);
      } else {
        ++g;
      }
    }
  }

  // A settled goal's window closes for nobody: its closing literal leaves
  // the world, the belief and the home's problem at once, and the running
  // mission's at the next arrival, so that it cannot end a later window of
  // the same senior early.
  void withdraw_window(const PerceivedGoal& g, double t) {
    if (g.window_end <= t) return;  // closed already
    pddl::TimedInitialLiteral close;
    close.time = g.window_end;
    close.positive = false;
    close.atom = domains::senior_atom(g.window, g.senior);
    std::erase_if(base_.timed_literals, [&](const pddl::TimedInitialLiteral& l) { return repair::same_literal(l, close); });
    belief_.withdraw(close);
    world_.cancel({g.window, g.senior}, false, g.window_end);
    withdrawn_.push_back(close);
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

  void log_plan(double t, const repair::ExecutingPlan& plan, const std::string& reason, double seconds) {
    LogEvent e{"plan", t, {}, {}, {}};
    const int id = ++plans_;
    e.payload = {{"plan_id", id}, {"reason", reason}, {"plan", repair::plan_text(plan)},
                 {"steps", steps_json(plan, loaded_.map)}, {"planning_seconds", seconds}};
    e.payload["supersedes"] = current_plan_ ? nlohmann::json(current_plan_) : nlohmann::json(nullptr);
    log_.write(e);
    current_plan_ = id;
    ++summary_.plans;
    summary_.merges += reason == "merge";
    record_planning(reason, seconds);
    // The world changes against the plans the deliberation makes for new
    // goals; a repair's plan meets what the world does next, not a draw of
    // its own (else failures would beget failures without end).
    if (reason != "repair" && settings_.failure_chance > 0 && coin() < settings_.failure_chance) {
      const std::vector<repair::ExogenousEvent> failure =
          events_.draw(plan, current_problem_, &loaded_.home.ontology, ++serial_);
      world_.schedule(failure);
      if (settings_.object_return_s > 0) world_.schedule(returns_.after_failure(failure));
    }
  }

  // Every planner call, plan found or not, by why it was made.
  void record_planning(const std::string& reason, double seconds) {
    summary_.planning_seconds.push_back(seconds);
    summary_.planning_by_reason[reason].push_back(seconds);
  }

  void on_monitor_event(const repair::MonitorEvent& m) {
    using Kind = repair::MonitorEvent::Kind;
    switch (m.kind) {
      case Kind::Plan: log_plan(m.time, *m.plan, m.reason, m.planning_seconds); return;
      case Kind::ActionStart:
      case Kind::ActionEnd: {
        LogEvent e{m.kind == Kind::ActionStart ? "action_start" : "action_end", m.time, {},
                   robot_of(m.action, loaded_.map), {}};
        e.payload = {{"action", m.action}, {"plan_id", current_plan_}};
        if (m.kind == Kind::ActionEnd && settings_.battery && !e.robot.empty()) {
          e.payload["battery"] = world_.value({"battery", e.robot}).value_or(0.0);
        }
        log_.write(e);
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
        explain(m.time, r.explanation.why, r.explanation.what, r.explanation.how);
        return;
      }
      case Kind::MergeFailed:
        record_planning("merge_failed", m.planning_seconds);
        explain(m.time, "new goals arrived while a plan ran", "no plan serves them with the goals in force",
                m.reason + "; they wait until the plan in force ends");
        merge_blocked_ = true;
        return;
    }
  }

  // An explanation names the seniors of the mission it explains.
  void explain(double t, const std::string& why, const std::string& what, const std::string& how) {
    std::string seniors;
    for (const std::string& s : mission_seniors_) seniors += (seniors.empty() ? "" : ", ") + s;
    LogEvent e{"explanation", t, seniors, {}, {}};
    e.payload = {{"why", why}, {"what", what}, {"how", how}};
    log_.write(e);
  }

  // What the monitor asks at every observation while a plan runs.
  std::optional<repair::GoalArrival> arrivals(double t, const repair::WorldState& believed) {
    if (!clock_.wait_until(t)) throw ClockStopped{};
    for (PerceivedGoal& g : perception_->sense(t)) pending_.push_back(std::move(g));
    settle(t, believed);
    if (pending_.empty() || merge_blocked_) return std::nullopt;
    return take_pending(t);
  }

  // The problem as an external planner would get it: time 0 is `now`
  // (the home plans from now in the task's own time), so that `alplan
  // plan` on the file meets the same deadlines.
  void keep_unplanned(double now) {
    if (settings_.unplanned_dir.empty()) return;
    std::filesystem::create_directories(settings_.unplanned_dir);
    const std::string stem = settings_.unplanned_dir + "/unplanned-" + std::to_string(++unplanned_);
    pddl::Problem from_now = current_problem_;
    for (pddl::TimedInitialLiteral& til : from_now.timed_literals) til.time -= now;
    std::erase_if(from_now.timed_literals, [](const pddl::TimedInitialLiteral& til) { return til.time <= 0.0; });
    std::ofstream(stem + ".pddl") << "; planned at " << now << " s of the run; times below are from then\n"
                                  << pddl::write_problem(from_now);
    if (unplanned_ == 1) std::ofstream(settings_.unplanned_dir + "/domain.pddl") << pddl::write_domain(*loaded_.home.files.domain);
  }

  // The robots this mission plans with (robot_dispatch.h), the others
  // taken out of `problem`; all of them when dispatching is off.
  std::vector<std::string> dispatch(pddl::Problem& problem) const {
    std::vector<std::string> all;
    for (const Placed& r : loaded_.map.robots) all.push_back(r.name);
    if (!settings_.dispatch) return all;
    std::vector<Call> calls;
    for (const PerceivedGoal& g : active_) calls.push_back({g.senior, g.window_end});
    std::vector<std::string> chosen = dispatch_robots(problem, all, calls);
    if (chosen.empty()) return all;
    problem = with_robots_only(problem, all, chosen);
    return chosen;
  }

  // With batteries, each robot of a mission must end it able to reach a
  // dock (domains::return_levels): the domain's reserve keeps plans safe,
  // this keeps a robot from being left at its reserve far from the dock,
  // where it could not move at all (home/README.md, Batteries).
  void require_return(pddl::Problem& problem, const std::vector<std::string>& robots) const {
    if (!settings_.battery) return;
    pddl::Condition all;
    all.kind = pddl::Condition::Kind::And;
    if (problem.goal) all.children.push_back(*problem.goal);
    for (const std::string& r : robots) {
      pddl::Condition enough;
      enough.kind = pddl::Condition::Kind::Comparison;
      enough.comparison = pddl::Comparison::GreaterEqual;
      pddl::NumericExpression level, at_least;
      level.kind = pddl::NumericExpression::Kind::Function;
      level.function.name = "battery";
      level.function.args.resize(1);
      level.function.args[0].name = r;
      at_least.value = return_levels_.at(r);
      enough.expressions = {level, at_least};
      all.children.push_back(enough);
    }
    problem.goal = all;
  }

  // Plans every goal in course from what the robots believe at t, then
  // executes under the monitor until the plan ends; returns the time then.
  double mission(double t) {
    replan_ = false;
    mission_seniors_.clear();
    for (const PerceivedGoal& g : active_) mission_seniors_.insert(g.senior);
    repair::GoalArrival arrival = take_pending(t);
    std::string motivation;
    for (const PerceivedGoal& g : active_) motivation += (motivation.empty() ? "" : "; ") + g.motivation;
    world_.advance(t);
    belief_.observe(world_.observe());
    pddl::Condition all;
    all.kind = pddl::Condition::Kind::And;
    for (const PerceivedGoal& g : active_) all.children.push_back(g.goal);
    pddl::Problem goal_problem = base_;
    goal_problem.goal = all;
    current_problem_ = repair::reformulate(loaded_.home.domain, goal_problem, belief_.state(), {}, t, 0.0);
    const std::vector<std::string> robots = dispatch(current_problem_);
    require_return(current_problem_, robots);
    const repair::PlanningOutcome planned =
        repair::plan_in_process(loaded_.home.domain, current_problem_, t, planner_);
    if (!planned.plan) {
      keep_unplanned(t);
      explain(t, motivation, "no plan reaches the goals in course in time",
              planned.message + "; the seniors are looked at again when their windows close");
      record_planning("none", planned.seconds);
      for (PerceivedGoal& g : active_) unplannable_.push_back(std::move(g));
      active_.clear();
      return t + settings_.step_s;
    }
    current_plan_ = 0;
    log_plan(t, *planned.plan, "initial", planned.seconds);
    repair::Mission m;
    m.domain = &loaded_.home.domain;
    m.problem = current_problem_;
    m.motivation = motivation;
    m.robot = robots.empty() ? loaded_.map.robots.front().name : robots.front();
    m.exogenous_predicates = domains::exogenous_predicates();
    m.start_time = t;
    m.on_event = [this](const repair::MonitorEvent& e) { on_monitor_event(e); };
    m.arrivals = [this](double now, const repair::WorldState& b) { return arrivals(now, b); };
    m.belief = &belief_;  // one belief: what this mission learns, the next knows
    repair::MonitorOptions options;
    options.step_size = settings_.step_s;
    // A home's plan runs long and meets many changes; a repair each is fine.
    options.max_repairs = 50;
    options.planner = replanner_;
    options.observation = observation_options();
    merge_blocked_ = false;
    const repair::Monitor monitor(options);
    const repair::ExecutionReport report =
        monitor.run(m, *planned.plan, world_, *strategy_, &world_, &loaded_.home.ontology);
    const double end = world_.finish_running(std::max(t + settings_.step_s, report.end_time));
    world_.advance(end);
    belief_.observe(world_.observe());
    keep_recognized(report);
    // Settled on what the robots believe, as during the mission.
    settle(end, belief_.state());
    if (!report.goal_reached) {
      explain(end, m.motivation, report.outcome, "the goals not reached are planned again while their windows last");
    }
    merge_blocked_ = false;
    // Goals still in course (a failed repair, a merge that found no plan)
    // are planned again from here.
    replan_ = !active_.empty();
    return end;
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
  ObjectReturns returns_;
  std::map<std::string, double> return_levels_;  // with batteries: per robot, enough to reach a dock
  std::mt19937_64 events_random_{settings_.seed * 104729 + 3};
  PlannerOptions planner_ = repair::executing_planner_options();
  PlannerOptions replanner_;
  std::unique_ptr<repair::RepairStrategy> strategy_;
  std::vector<PerceivedGoal> pending_, active_;
  std::vector<PerceivedGoal> unplannable_;  // no plan found: they wait for their windows to close
  std::vector<pddl::TimedInitialLiteral> withdrawn_;  // windows of settled goals, for the running mission
  std::set<std::string> mission_seniors_;  // whose goals the mission in course serves
  bool replan_ = false;
  pddl::Problem current_problem_;
  bool merge_blocked_ = false;
  int plans_ = 0, current_plan_ = 0, serial_ = 0, unplanned_ = 0;
  HomeSummary summary_;
};

}  // namespace

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto at = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(at, values.size() - 1)];
}

nlohmann::json HomeSummary::json() const {
  nlohmann::json j = {{"goals", goals},         {"comforted", comforted},     {"within_window", within_window},
          {"windows_missed", windows_missed}, {"failures", failures}, {"plans", plans},
          {"merges", merges},       {"repairs", repairs},         {"repairs_failed", repairs_failed},
          {"objects_recognized", objects_recognized},
          {"planning_p50_s", quantile(planning_seconds, 0.5)}, {"planning_p95_s", quantile(planning_seconds, 0.95)},
          {"episodes", episodes},   {"episodes_detected", episodes_detected}, {"false_alarms", false_alarms}, {"end_time", end_time}};
  if (batteries.empty()) return j;  // runs without batteries: as before
  nlohmann::json& b = j["batteries"];
  for (const auto& [robot, r] : batteries) {
    b[robot] = {{"level", r.level}, {"lowest", r.lowest}, {"reserve", r.reserve}, {"below_reserve", r.below_reserve}};
  }
  return j;
}

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
