#include "repair/monitor.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <utility>

#include "pddl_parser/writer.h"
#include "planner/formula_evaluation.h"
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

MonitorEvent snap_event(MonitorEvent::Kind kind, double t, const std::string& action) {
  MonitorEvent event;
  event.kind = kind;
  event.time = t;
  event.action = action;
  return event;
}

// An action a replaced plan had started: the new plan takes it as given
// (it was compiled into the problem), but its end must still be dispatched.
struct CommittedEnd {
  std::shared_ptr<const GroundTask> task;
  ActionId action = 0;
  double end = 0.0;
  double duration = 0.0;
};

// An action the world had not finished when the plan said it would (an
// overrun): it goes on under its over-all condition (a move still draining
// the battery) until the world reports it ended.
struct Overrun {
  std::shared_ptr<const GroundTask> task;
  std::shared_ptr<const StateMapping> mapping;
  ActionId action = 0;
  double duration = 0.0;
  std::string name;
  bool reported = false;  // its invariant failed once: one failure, not one per look
};

// A foreseen failure no repair could mend yet, and what the monitor had
// seen when it tried (Belief's changes counted).
struct DeferredFailure {
  std::string action, condition;
  std::size_t news = 0;
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


nlohmann::json ExecutionReport::json() const {
  nlohmann::json repairs_json = nlohmann::json::array();
  for (const RepairRecord& r : repairs) {
    repairs_json.push_back({{"time", r.failure.time},
                            {"kind", to_string(r.failure.kind)},
                            {"action", r.failure.action},
                            {"condition", r.failure.condition},
                            {"foreseen", r.foreseen},
                            {"deferred", r.deferred},
                            {"search", r.search},
                            {"strategy", r.strategy},
                            {"fallback", r.fallback},
                            {"perception_seconds", r.perception_seconds},
                            {"repaired", r.repaired},
                            {"seconds", r.seconds},
                            {"planner_calls", r.planner_calls},
                            {"reused_grounding", r.reused_grounding},
                            {"plan_distance", r.plan_distance},
                            {"plan", r.plan_text},
                            {"explanation", r.explanation.json()}});
  }
  return {{"initial_plan", initial_plan_text}, {"preparation_seconds", preparation_seconds}, {"repairs", repairs_json}, {"goal_reached", goal_reached}, {"void_actions", void_actions},
          {"end_time", end_time}, {"outcome", outcome}, {"events", events},
          {"observation", to_string(observation)}, {"sightings", sightings}};
}

// One execution: the plan in force, what has been dispatched, the report.
class MonitoredExecution::Impl {
 public:
  Impl(const MonitorOptions& options, const Mission& mission, ExecutingPlan plan, World& world,
            RepairStrategy& strategy, ObjectRecognizer* recognizer, const TypeOntology* ontology)
      : options_(options), mission_(mission), world_(world), strategy_(strategy), recognizer_(recognizer),
        ontology_(ontology), problem_(mission.problem), motivation_(mission.motivation),
        belief_(mission.belief ? *mission.belief : own_belief_.emplace(mission.problem, options.observation)) {
    report_.initial_plan_text = plan_text(plan);
    report_.observation = options.observation.model;
    goal_ = problem_.goal ? pddl::write_condition(*problem_.goal) : "(and)";
    adopt(with_all_conditions(plan));
    if (options_.reuse_grounding) prepare_grounding();
  }

  double first_look() const {
    return plan_.steps.empty() ? mission_.start_time : std::min(mission_.start_time, plan_.steps.front().start);
  }

  // Looks at t until it has nothing more to do at t (a repaired or merged
  // plan is looked at again at once); returns the next look, or nothing
  // once the run has ended.
  std::optional<double> step(double t) {
    if (ended_) return std::nullopt;
    for (int same_time = 0; same_time < 1000; ++same_time) {
      if (++looks_ > 1000000) break;
      world_.advance(t);
      belief_.observe(world_.observe());
      learn_from_void_actions();
      if (take_arrivals(t)) continue;  // look again at the same time, with the merged plan
      const WorldState observed = belief_.state();
      remember(observed, t);
      const ExplicitState state = mapping_->to_explicit(observed);
      // An overrun's own invariant first: a battery run down below its
      // reserve is why the steps after it fail, not the other way round.
      std::optional<Violation> failure = check_overruns(t, observed);
      if (!failure) failure = timeline_->check_due(t, state);
      bool foreseen = false;
      if (!failure && options_.lookahead) {
        failure = timeline_->check_ahead(t, state);
        foreseen = failure.has_value();
      }
      if (!failure && finished() && t + tolerance() >= timeline_->end_time()) {
        failure = timeline_->check_goal(t, state);
        if (!failure) {
          done(true, "the goal " + goal_ + " holds at " + time_text(t), t);
          return std::nullopt;
        }
      }
      if (failure && foreseen && waiting_for_news(*failure)) failure.reset();
      if (failure && awaiting_overrun(*failure)) awaited_ = std::exchange(failure, std::nullopt);
      if (!failure && awaited_) {
        if (awaiting_overrun(*awaited_)) {
          // Nothing is dispatched meanwhile (the plan's next steps need the
          // action's end), and the plan's own times are stale: look again soon.
          return t + options_.step_size;
        }
        // Seen to end: the steps that waited on it are late, plan again now
        // (the failure keeps its time: the condition failed then).
        failure = awaited_;
      }
      awaited_.reset();
      if (failure) {
        const Attempt attempt = repair(*failure, foreseen, observed, t);
        if (attempt == Attempt::Ended) return std::nullopt;
        if (attempt == Attempt::Repaired) continue;  // look again at the same time, with the new plan
      }
      if (options_.proactive && look_for_alternative(observed, t)) continue;
      dispatch(t);
      // Once the last end is dispatched, judge the goal at once, not a step later.
      if (!finished() || t + tolerance() < timeline_->end_time()) return next_time(t);
    }
    done(false, "the monitor stopped: too many observations", t);
    return std::nullopt;
  }

  bool ended() const { return ended_; }
  const ExecutionReport& report() const { return report_; }
  const ExecutingPlan& plan() const { return plan_; }
  const pddl::Problem& problem() const { return problem_; }

  // An action of the robot's that aborted tells it the literal that stopped
  // it (the executive's feedback), even where no sensor looks: without it,
  // a belief the world contradicts out of view would make the same plan
  // fail the same way again and again.
  void learn_from_void_actions() {
    for (const VoidAction& v : world_.void_actions_since(void_seen_)) {
      ++void_seen_;
      if (!started_.count(v.action)) continue;  // another robot's
      aborted_.insert(v.action);
      if (!v.literal.empty()) belief_.learned(v.literal, v.holds);
      ++report_.void_actions;
      report_.events.push_back(time_text(v.time) + ": " + v.action + " came to nothing: " + v.why);
    }
  }

  // The actions this execution started that the world still runs.
  std::vector<ActionInProgress> running() const {
    std::vector<ActionInProgress> own = world_.in_progress();
    // One it knows aborted will change nothing when it ends: not a commitment.
    std::erase_if(own, [&](const ActionInProgress& a) { return !started_.count(a.name) || aborted_.count(a.name); });
    return own;
  }

 private:
  double tolerance() const { return plan_.epsilon / 10.0; }
  bool finished() const {
    return committed_.empty() && std::all_of(progress_.ended.begin(), progress_.ended.end(), [](bool e) { return e; });
  }

  ExecutionReport done(bool reached, const std::string& outcome, double t) {
    ended_ = true;
    report_.sightings = belief_.sightings().size();
    report_.goal_reached = reached;
    report_.end_time = t;
    report_.outcome = outcome;
    if (reached) report_.events.push_back(time_text(t) + ": goal reached");
    return report_;
  }

  void adopt(ExecutingPlan plan) {
    for (std::size_t s = 0; s < plan_.steps.size(); ++s) {
      if (progress_.started[s] && !progress_.ended[s]) {
        committed_.push_back({plan_.task, plan_.steps[s].action, plan_.steps[s].end(), plan_.steps[s].duration});
      }
    }
    deferred_.reset();
    plan_ = std::move(plan);
    timeline_ = std::make_unique<Timeline>(plan_);
    mapping_ = std::make_unique<StateMapping>(*plan_.task);
    progress_ = Progress(plan_.steps.size());
  }

  // Grounds the problem now, while nothing has failed, so that a repair
  // finds the grounding (and the planner's structures for it) ready. A problem grounding rejects is left to the
  // repairs to report.
  void prepare_grounding() {
    const auto began = std::chrono::steady_clock::now();
    GroundingOptions grounding;
    grounding.names.exogenous_predicates = mission_.exogenous_predicates;
    grounding_ = std::make_unique<GroundingCache>(grounding);
    try {
      *grounding_->planner_workspace() = prepare_workspace(grounding_->ground(*mission_.domain, problem_), options_.planner.prune_irrelevant);
    } catch (const std::exception&) {
    }
    report_.preparation_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  }

  RepairRequest request(const Violation& failure, const WorldState& observed, double t) const {
    RepairRequest r;
    r.domain = mission_.domain;
    r.problem = &problem_;
    r.plan = &plan_;
    r.failure = &failure;
    r.observed = observed;
    r.in_progress = known_in_progress(t);
    r.now = t;
    r.robot_location = location_of(observed, mission_.robot);
    r.sightings = belief_.sightings();
    r.recognizer = recognizer_;
    r.ontology = ontology_;
    r.grounding = grounding_.get();
    if (!history_.empty()) r.history = &history_;
    return r;
  }

  // The trajectory believed so far, for PDDL 3 constraints: each change,
  // kept only when the problem has constraints (a home's day of
  // observations is long, and nothing else reads it).
  void remember(const WorldState& observed, double t) {
    if (!problem_.constraints) return;
    if (!history_.empty() && history_.back().atoms == observed.atoms && history_.back().values == observed.values) return;
    history_.push_back(observed);
    history_.back().time = t;
  }

  // The first part of an explanation: the plan in force and why it was made.
  std::string why_the_plan() const { return motivation_ + "; the plan's goal was " + goal_; }

  RepairRecord record_of(const Violation& failure, bool foreseen, const RepairResult& result,
                         const std::string& strategy, double t, const std::string& why) const {
    RepairRecord record;
    record.failure = failure;
    record.foreseen = foreseen;
    record.strategy = strategy;
    record.fallback = result.fallback;
    record.perception_seconds = result.perception_seconds;
    record.repaired = result.repaired;
    record.seconds = result.seconds;
    record.planner_calls = result.planner_calls;
    record.reused_grounding = result.reused_grounding;
    record.integrated = result.integrated;
    record.explanation.why = why;
    record.explanation.what = failure.kind == Violation::Kind::Unsupported ? failure.condition
                                                                           : describe_failure(failure, foreseen);
    record.explanation.how = result.how.empty() ? strategy + " found no repair" : result.how;
    record.explanation.repaired = result.repaired;
    if (result.repaired) {
      record.plan_text = plan_text(*result.plan);
      record.plan_distance = plan_distance(plan_, *result.plan, t);
    }
    return record;
  }

  enum class Attempt : unsigned char { Repaired, Deferred, Ended };

  // An action seen to overrun whose end will make the failed condition
  // hold: the robot cannot know how much longer it takes (the world's own
  // estimate is not a sensor), so it waits to see the action end and
  // repairs from what it sees then, instead of planning around a guess.
  bool awaiting_overrun(const Violation& failure) const {
    if (overrunning_.empty()) return false;
    for (const ActionInProgress& a : world_.in_progress()) {
      if (!overrunning_.count(a.name)) continue;
      for (const AtomKey& k : a.adds) {
        if (to_string(k) == failure.condition) return true;
      }
    }
    return false;
  }

  // What the robot knows of its actions underway: which run, what their
  // ends change, and when they end as planned; an action seen to overrun
  // ends, as far as it knows, no earlier than its next look.
  std::vector<ActionInProgress> known_in_progress(double t) const {
    std::vector<ActionInProgress> known = running();
    for (ActionInProgress& a : known) {
      if (overrunning_.count(a.name)) a.expected_end = t + options_.step_size;
    }
    return known;
  }

  // A foreseen failure tried before, with nothing new seen since.
  bool waiting_for_news(const Violation& failure) const {
    return deferred_ && deferred_->action == failure.action && deferred_->condition == failure.condition &&
           deferred_->news == belief_.news();
  }

  std::size_t final_repairs() const {
    return static_cast<std::size_t>(std::count_if(report_.repairs.begin(), report_.repairs.end(),
                                                  [](const RepairRecord& r) { return !r.deferred && !r.search; }));
  }

  Attempt repair(const Violation& failure, bool foreseen, const WorldState& observed, double t) {
    report_.events.push_back(time_text(t) + ": failure: " + describe_failure(failure, foreseen));
    const bool search_step = belief_.search().assumed(failure.condition);
    if (!search_step && static_cast<int>(final_repairs()) >= options_.max_repairs) {
      done(false, "gave up after " + std::to_string(final_repairs()) + " repairs: " +
                      describe_failure(failure, foreseen), t);
      return Attempt::Ended;
    }
    // Why the plan that failed was made, before goal generation moves on.
    const std::string why = why_the_plan();
    const std::optional<std::string> new_goal = regenerate_goal(observed, t);
    RepairResult result = strategy_.repair(request(failure, observed, t));
    report_.repairs.push_back(record_of(failure, foreseen, result, strategy_.name(), t, why));
    report_.repairs.back().search = search_step;
    note_search(report_.repairs.back());
    if (new_goal) {
      std::string& how = report_.repairs.back().explanation.how;
      how = *new_goal + "; " + how;
    }
    tell({MonitorEvent::Kind::Failure, t, failure.action, {}, nullptr, &report_.repairs.back()});
    tell({MonitorEvent::Kind::Repair, t, failure.action, {}, nullptr, &report_.repairs.back()});
    if (!result.repaired && foreseen && options_.defer_foreseen) {
      // Not due yet: carry on and look again when something new is seen.
      RepairRecord& record = report_.repairs.back();
      record.deferred = true;
      record.explanation.how += "; the failure is not due yet, so the robot carries on and the monitor will try "
                                "again when it sees something new";
      deferred_ = DeferredFailure{failure.action, failure.condition, belief_.news()};
      report_.events.push_back(time_text(t) + ": " + strategy_.name() + " cannot repair yet: " + result.how +
                               "; carrying on");
      return Attempt::Deferred;
    }
    if (!result.repaired) {
      report_.events.push_back(time_text(t) + ": " + strategy_.name() + " could not repair: " + result.how);
      done(false, "no repair: " + result.how, t);
      return Attempt::Ended;
    }
    report_.events.push_back(time_text(t) + ": repaired by " + strategy_.name() + ": " + result.how);
    for (const RecognizedObject& o : result.integrated) belief_.know(o.name);
    problem_ = std::move(result.problem);
    adopt(with_all_conditions(*result.plan));
    tell({MonitorEvent::Kind::Plan, t, {}, "repair", &plan_, nullptr, result.seconds});
    return Attempt::Repaired;
  }

  // A failure of a guess of the search for a lost person, or the failure
  // that lost them: the explanation says where the robot has looked and
  // where it looks next.
  void note_search(RepairRecord& record) const {
    const PersonSearch& search = belief_.search();
    const AtomKey failed = words_of(record.failure.condition);  // not one atom: no location fact
    if (failed.size() != 3 || failed[0] != options_.observation.location_predicate) return;
    const std::optional<PersonSearch::Status> status = search.status(failed[1]);
    if (!status) return;
    std::string looked;
    for (const std::string& room : status->looked_in) looked += (looked.empty() ? "" : ", ") + room;
    record.explanation.what += "; the robot lost sight of " + status->person + " at " + time_text(status->lost_at) +
                               " and has looked in " + looked;
    record.explanation.what += status->guess ? ", so it looks next in " + *status->guess +
                                                   ", the nearest place it has not looked in"
                                             : ", every place it can reach";
  }

  // Is the goal still the right one? An emotion may have changed. Returns
  // the change, in words, when there is one.
  std::optional<std::string> regenerate_goal(const WorldState& observed, double t) {
    if (!mission_.goal_generator) return std::nullopt;
    auto generated = mission_.goal_generator(observed);
    if (!generated) return std::nullopt;
    const std::string goal = pddl::write_condition(generated->first);
    if (goal == goal_) return std::nullopt;
    const std::string change = "goal generation: " + generated->second + ", so the goal is now " + goal;
    report_.events.push_back(time_text(t) + ": " + change);
    problem_.goal = generated->first;
    motivation_ = generated->second;
    goal_ = goal;
    return change;
  }

  // The paper's Discussion: look for a better course of action even when
  // nothing has failed (a new object nearby, a shorter way). Switches only
  // for a clear gain, so that the robot does not dither.
  bool look_for_alternative(const WorldState& observed, double t) {
    Violation none;
    none.kind = Violation::Kind::Unsupported;
    none.time = t;
    none.condition = "nothing failed; the monitor looked for a better plan at " + time_text(t);
    RepairRequest r = request(none, observed, t);
    pddl::Problem known = problem_;
    const std::vector<RecognizedObject> seen = integrate_recognized(r, known);
    if (seen.empty()) return false;  // the world offers nothing new
    // Anytime, briefly: the first plan found may be a costly shortcut (a
    // suggestion) that the metric would never choose.
    PlannerOptions planner = options_.planner;
    planner.epsilon = plan_.epsilon;
    planner.search = with_anytime(planner.search);
    planner.time_limit = std::min(planner.time_limit, options_.proactive_budget);
    RepairResult result = replan_from(r, *mission_.domain, known, planner);
    result.integrated = seen;
    if (!result.repaired) return false;
    double current = 0.0, alternative = 0.0;
    for (const ScheduledAction& s : plan_.steps) current = std::max(current, s.end());
    for (const ScheduledAction& s : result.plan->steps) alternative = std::max(alternative, s.end());
    if (alternative > current - options_.proactive_gain) return false;
    result.how = "switched to a plan that ends at " + time_text(alternative) + " instead of " + time_text(current) +
                 ": " + describe_remedy(*result.plan, t);
    report_.repairs.push_back(record_of(none, false, result, "proactive", t, why_the_plan()));
    report_.events.push_back(time_text(t) + ": proactive: " + result.how);
    for (const RecognizedObject& o : result.integrated) belief_.know(o.name);
    problem_ = std::move(result.problem);
    adopt(with_all_conditions(*result.plan));
    tell({MonitorEvent::Kind::Plan, t, {}, "proactive", &plan_, nullptr, result.seconds});
    return true;
  }

  void tell(const MonitorEvent& event) const {
    if (mission_.on_event) mission_.on_event(event);
  }

  // New goals from the home's deliberation: told to the belief at once, and
  // planned with the old goal from what the robot believes now. Returns
  // true when the plan changed.
  bool take_arrivals(double t) {
    if (!mission_.arrivals) return false;
    const std::optional<GoalArrival> arrival = mission_.arrivals(t, belief_.state());
    if (!arrival) return false;
    world_.advance(t);  // what the deliberation scheduled for now
    belief_.observe(world_.observe());
    for (const auto& [fact, value] : arrival->facts) belief_.told(fact, value);
    for (const pddl::TimedInitialLiteral& gone : arrival->withdrawn) {
      belief_.withdraw(gone);
      std::erase_if(problem_.timed_literals, [&](const pddl::TimedInitialLiteral& l) { return same_literal(l, gone); });
    }
    for (const pddl::TimedInitialLiteral& l : arrival->timed_literals) belief_.expect(l);
    pddl::Problem merged = problem_;
    pddl::Condition all;
    all.kind = pddl::Condition::Kind::And;
    if (merged.goal) all.children.push_back(*merged.goal);
    all.children.insert(all.children.end(), arrival->goals.begin(), arrival->goals.end());
    merged.goal = all;
    merged.timed_literals.insert(merged.timed_literals.end(), arrival->timed_literals.begin(),
                                 arrival->timed_literals.end());
    if (arrival->preferences) {
      merged.constraints = arrival->preferences->constraints;
      merged.metric = arrival->preferences->metric;
    }
    Violation none;
    none.kind = Violation::Kind::Unsupported;
    none.time = t;
    none.condition = "new goals: " + arrival->motivation;
    const RepairRequest r = request(none, belief_.state(), t);
    PlannerOptions planner = options_.planner;
    planner.epsilon = plan_.epsilon;
    const RepairResult result = replan_from(r, *mission_.domain, merged, planner);
    if (!result.repaired) {
      // The goals in force stay; the caller decides what becomes of the new.
      problem_.timed_literals = merged.timed_literals;
      tell({MonitorEvent::Kind::MergeFailed, t, {}, result.how, nullptr, nullptr, result.seconds});
      return false;
    }
    report_.events.push_back(time_text(t) + ": new goals merged: " + arrival->motivation);
    problem_ = result.problem;
    motivation_ += "; " + arrival->motivation;
    goal_ = pddl::write_condition(*merged.goal);
    adopt(with_all_conditions(*result.plan));
    tell({MonitorEvent::Kind::Plan, t, {}, "merge", &plan_, nullptr, result.seconds});
    return true;
  }

  // Dispatches what happens now: ends first, then starts.
  void dispatch(double t) {
    for (auto c = committed_.begin(); c != committed_.end();) {
      if (c->end > t + tolerance()) {
        ++c;
        continue;
      }
      if (world_.end_action(*c->task, c->action, t)) {
        belief_.act(*c->task, c->action, false, c->duration);
      } else {
        overran(c->task, c->action, c->duration);
      }
      tell(snap_event(MonitorEvent::Kind::ActionEnd, t, c->task->action_name(c->task->actions[c->action])));
      c = committed_.erase(c);
    }
    for (std::size_t s = 0; s < plan_.steps.size(); ++s) {
      const ScheduledAction& a = plan_.steps[s];
      const bool durative = plan_.task->actions[a.action].durative;
      if (durative && progress_.started[s] && !progress_.ended[s] && std::abs(a.end() - t) <= tolerance()) {
        if (world_.end_action(*plan_.task, a.action, t)) {
          belief_.act(*plan_.task, a.action, false, a.duration);
        } else {
          report_.events.push_back(time_text(t) + ": " + a.name + " has not finished as planned");
          overran(plan_.task, a.action, a.duration);
        }
        progress_.ended[s] = true;
        tell(snap_event(MonitorEvent::Kind::ActionEnd, t, a.name));
      }
    }
    for (std::size_t s = 0; s < plan_.steps.size(); ++s) {
      const ScheduledAction& a = plan_.steps[s];
      if (progress_.started[s] || std::abs(a.start - t) > tolerance()) continue;
      world_.start_action(*plan_.task, a.action, t, a.duration);
      started_.insert(a.name);
      aborted_.erase(a.name);
      belief_.act(*plan_.task, a.action, true, a.duration);
      progress_.started[s] = true;
      if (!plan_.task->actions[a.action].durative) progress_.ended[s] = true;
      report_.events.push_back(time_text(t) + ": start " + a.name);
      tell(snap_event(MonitorEvent::Kind::ActionStart, t, a.name));
    }
  }

  // Only actions that change values continuously are watched past their
  // planned end: their invariants bind what keeps changing while they run
  // on (a battery draining). A discrete action's overrun shows in the
  // conditions of the steps after it, as it always has.
  void overran(const std::shared_ptr<const GroundTask>& task, ActionId action, double duration) {
    const GroundAction& a = task->actions[action];
    overrunning_.insert(task->action_name(a));
    if (a.over_all.empty() || a.continuous.empty()) return;
    overruns_.push_back({task, std::make_shared<StateMapping>(*task), action, duration, task->action_name(a)});
  }

  // The over-all conditions of overrunning actions the world still runs,
  // against what the robot observes (its battery gauge among the values);
  // the timeline's own entries end where the plan said the actions would.
  std::optional<Violation> check_overruns(double t, const WorldState& observed) {
    if (overruns_.empty()) return std::nullopt;
    std::set<std::string> running;  // whether each still runs, not when it will end
    for (const ActionInProgress& a : world_.in_progress()) running.insert(a.name);
    std::erase_if(overruns_, [&](const Overrun& o) { return !running.count(o.name); });
    for (Overrun& o : overruns_) {
      if (o.reported) continue;
      const GroundAction& a = o.task->actions[o.action];
      EvaluationContext context;
      context.duration = o.duration;
      std::optional<Unsatisfied> failed;
      try {
        // The slack the validator gives values that change with time.
        failed = first_unsatisfied(a.over_all, o.mapping->to_explicit(observed), context, kNumericSlack);
      } catch (const EvaluationError&) {
        continue;  // a value the world does not report: nothing to judge by
      }
      if (!failed) continue;
      o.reported = true;
      Violation v;
      v.kind = Violation::Kind::UnsatisfiedInvariant;
      v.time = t;
      v.until = t + options_.step_size;  // its end is unknown: at the earliest, the next look
      v.action = o.name;
      v.condition = describe(*o.task, a.over_all, *failed);
      return v;
    }
    return std::nullopt;
  }

  double next_time(double t) const { return next_observation(*timeline_, committed_, t, options_.step_size); }

  const MonitorOptions options_;  // copies: the caller may step it long after it made it
  const Mission mission_;
  World& world_;
  RepairStrategy& strategy_;
  ObjectRecognizer* recognizer_;
  const TypeOntology* ontology_;
  pddl::Problem problem_;
  std::string motivation_;
  std::string goal_;
  ExecutingPlan plan_;
  std::unique_ptr<Timeline> timeline_;
  std::unique_ptr<StateMapping> mapping_;
  Progress progress_{0};
  std::vector<CommittedEnd> committed_;
  std::vector<Overrun> overruns_;
  std::set<std::string> overrunning_;  // actions seen to run past their planned end
  std::optional<Violation> awaited_;    // a failure put off until an overrun is seen to end
  ExecutionReport report_;
  std::unique_ptr<GroundingCache> grounding_;
  std::optional<Belief> own_belief_;  // when the mission brings none
  Belief& belief_;
  std::vector<WorldState> history_;
  std::set<std::string> started_;  // names of the actions it started: the others are other robots'
  std::size_t void_seen_ = 0;  // of the world's void actions, those looked at
  std::set<std::string> aborted_;  // its running actions it knows came to nothing
  bool ended_ = false;
  long looks_ = 0;
  std::optional<DeferredFailure> deferred_;
};

MonitoredExecution::MonitoredExecution(const MonitorOptions& options, const Mission& mission, ExecutingPlan plan,
                                       World& world, RepairStrategy& strategy, ObjectRecognizer* recognizer,
                                       const TypeOntology* ontology)
    : impl_(std::make_unique<Impl>(options, mission, std::move(plan), world, strategy, recognizer, ontology)) {}
MonitoredExecution::~MonitoredExecution() = default;
double MonitoredExecution::first_look() const { return impl_->first_look(); }
std::optional<double> MonitoredExecution::step(double t) { return impl_->step(t); }
bool MonitoredExecution::ended() const { return impl_->ended(); }
const ExecutionReport& MonitoredExecution::report() const { return impl_->report(); }
const ExecutingPlan& MonitoredExecution::plan() const { return impl_->plan(); }
const pddl::Problem& MonitoredExecution::problem() const { return impl_->problem(); }
std::vector<ActionInProgress> MonitoredExecution::running() const { return impl_->running(); }

ExecutionReport Monitor::run(const Mission& mission, ExecutingPlan plan, World& world, RepairStrategy& strategy,
                             ObjectRecognizer* recognizer, const TypeOntology* ontology) const {
  MonitoredExecution execution(options_, mission, std::move(plan), world, strategy, recognizer, ontology);
  for (std::optional<double> t = execution.first_look(); t;) t = execution.step(*t);
  return execution.report();
}

}  // namespace alplan::repair
